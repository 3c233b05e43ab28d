# The error analysis (paper_notes/error_analysis.md): one figure per statement, measured error and
# bound against h (and against the impact k for Statement 3), direct_located against the schemes,
# and the campaign's ratios measured / bound. Its statements are the package's own error analysis,
# numbered by statement (Lemma 1.2 is the second lemma of Statement 1): the figures call them "EA
# Lemma 1.2" etc., apart from the paper's Lemmas 1-5.
# Usage: gnuplot -e "results='results/error_analysis'" experiments/error_analysis/plot.gp
if (!exists("results")) results = 'results/error_analysis'
data(name) = results.'/'.name.'.csv'
set datafile separator ','

direct = "#0072B2"
mj = "#009E73"
fb = "#56B4E9"
located = "#D55E00"
bound = "#000000"
grey = "#808080"
# Figure 4's first impact: V = sqrt(v0^2 + 2 g u0), COR e = 0.75.
g = 9.80665
V = sqrt(1 + 2 * g * 5)
e = 0.75

do for [format in "png svg"] {
  # ---- Statement 1 ----
  if (format eq "png") {
    set terminal pngcairo size 1300,520 font ",10"
    set output 'figures/error_analysis_flight.png'
  } else {
    set terminal svg size 1300,520 font ",10" dynamic
    set output 'figures/error_analysis_flight.svg'
  }
  set multiplot layout 1,2 title "Error analysis (EA, beyond the paper), Statement 1, free flight: each scheme against the exact flight before the first impact"
  set grid
  set logscale xy
  set xrange [*:*] noextend
  set autoscale y
  # The log axes a little past the data, which a range from the data would touch at its ends.
  set offsets graph 0.03, graph 0.03, 0, 0
  set format x "10^{%T}"
  set format y "10^{%T}"
  set xlabel "time step h [s]"
  set key below maxrows 2 nobox font ",9" title " "
  set title "(a) f(t) = -9.80665 + 30 sin(5 t + 0.3) m/s^2: bound of EA Lemma 1.2"
  set ylabel "max_l |u^l - u(t_l)| [m]"
  plot data('flight') skip 1 using 1:2 with points pt 7 ps 0.9 lc rgb direct title "direct (5-1)", \
       '' skip 1 using 1:3 with points pt 6 ps 1.4 lc rgb mj title "moreau\\_jean", \
       '' skip 1 using 1:4 with lines lw 2 lc rgb bound title "bound a h^2 min(2, ω t) / (12 (1 - (ωh/2π)^2))"
  set title "(b) fb\\_newton's smoothing before Figure 4's first impact\n(t_1 = 0.913 s), T = 0.9 s: bound of EA Lemma 1.3"
  set ylabel "max_l |fb\\_newton - exact| [m, m/s]"
  set yrange [1e-19 : *]  # fixed range: exact zeros are drawn at 1e-19, the axis bottom
  plot data('flight') skip 1 using 1:($5 > 0 ? $5 : 1e-19) with points pt 7 ps 0.9 lc rgb fb title "u (0 drawn at 10^{-19})", \
       '' skip 1 using 1:6 with lines lw 2 lc rgb bound title "bound on u: Σ kicks (t_l - t_j)", \
       '' skip 1 using 1:($7 > 0 ? $7 : 1e-19) with points pt 6 ps 0.9 lc rgb located title "v", \
       '' skip 1 using 1:8 with lines dt 2 lw 2 lc rgb bound title "bound on v: Σ kicks, kick <= min(ε^{1/2}, hε/(2d))"
  unset multiplot
  set yrange [*:*]

  # ---- Statement 2 ----
  if (format eq "png") {
    set terminal pngcairo size 1300,1000 font ",10"
    set output 'figures/error_analysis_impact.png'
  } else {
    set terminal svg size 1300,1000 font ",10" dynamic
    set output 'figures/error_analysis_impact.svg'
  }
  set multiplot layout 2,2 title sprintf("EA Statement 2 (one impact): Figure 4's first impact (u^0 = 5 m, v^0 = -1 m/s, f = -9.80665 m/s^2, V = %.3f m/s), 300 step sizes 10^{-4}..2x10^{-2} s", V)
  unset logscale
  set format x "%g"
  set format y "%g"
  set xlabel "fraction of the contact step flown before the floor, θ (moreau\\_jean: σ) [1]"
  set ylabel "u_h - u one step after the impact, over V h [1]"
  set bmargin 8
  set key below maxrows 2 nobox font ",9" title " "
  set title "(a) position error after the impact, COR e = 0.75: EA Lemmas 2.1, 2.3"
  set xrange [*:*] noextend
  set samples 400
  plot data('impact') skip 1 using 2:($3 / (V * $1)) with points pt 7 ps 0.5 lc rgb direct title "direct", \
       (x >= 0 ? -e * (1 - x) : NaN) with lines lw 2 lc rgb direct title "-e (1 - θ) (EA Lemma 2.1, h -> 0)", \
       data('impact') skip 1 using 9:($10 / (V * $1)) with points pt 6 ps 0.5 lc rgb mj title "moreau\\_jean", \
       (abs(x) <= 0.5 ? (1 + e) * (x - 0.5) : NaN) with lines lw 2 dt 2 lc rgb mj title "(1 + e)(σ - 1/2) (EA Lemma 2.3, h -> 0)"
  set title "(b) without COR: the scheme's COR, leave speed over V (EA Lemma 2.2, C24)"
  set xrange [0 : 1]  # fixed range: θ is a fraction of the step, drawn whole
  set xlabel "θ [1]"
  set ylabel "effective COR W / V [1]"
  plot data('impact') skip 1 using 14:15 with points pt 7 ps 0.5 lc rgb direct title "direct, measured", \
       abs(1 - 2 * x) with lines lw 2 lc rgb bound title "|1 - 2θ|"
  set title "(c) direct with COR: errors and their bounds (EA Lemma 2.1)"
  set logscale xy
  set format x "10^{%T}"
  set format y "10^{%T}"
  set xrange [*:*] noextend
  set xlabel "time step h [s]"
  set ylabel "error [m, m/s, s]"
  set key below maxrows 3 nobox font ",9" title " "
  plot data('impact') skip 1 using 1:(abs($3)) with points pt 7 ps 0.5 lc rgb direct title "|du| [m]", \
       '' skip 1 using 1:4 with lines lw 2 lc rgb direct title "h (e V + |f| h / 2)", \
       '' skip 1 using 1:(abs($5)) with points pt 6 ps 0.5 lc rgb located title "|dv| [m/s]", \
       '' skip 1 using 1:6 with lines lw 2 lc rgb located title "|f| h", \
       '' skip 1 using 1:7 with points pt 5 ps 0.4 lc rgb grey title "linear crossing time [s]", \
       '' skip 1 using 1:8 with lines lw 2 lc rgb grey title "|f| h^2 / (2 (V - |f| h))"
  set title "(d) moreau\\_jean: errors and their bounds (EA Lemma 2.3)"
  plot data('impact') skip 1 using 1:(abs($10)) with points pt 7 ps 0.5 lc rgb mj title "|du| [m]", \
       '' skip 1 using 1:11 with lines lw 2 lc rgb mj title "(1 + e) V h (1 + |f|h/(8V)) + h |dv|_{max} / 2", \
       '' skip 1 using 1:(abs($12)) with points pt 6 ps 0.5 lc rgb located title "|dv| [m/s]", \
       '' skip 1 using 1:13 with lines lw 2 lc rgb located title "|f| h (1 + (1 + e)(1/2 + |f|h/(8V)))"
  unset multiplot
  set bmargin

  # ---- Statement 3 ----
  if (format eq "png") {
    set terminal pngcairo size 1300,1000 font ",10"
    set output 'figures/error_analysis_zeno.png'
  } else {
    set terminal svg size 1300,1000 font ",10" dynamic
    set output 'figures/error_analysis_zeno.svg'
  }
  set multiplot layout 2,2 title "EA Statement 3 (many impacts): Figure 4 with COR e = 0.75 (u^0 = 5 m, v^0 = -1 m/s, f = -9.80665 m/s^2, T = 10 s, Zeno time 7.0026 s)"
  set title "(a) impact times of direct, |t_k^h - t_k|, against the impact k (EA Theorem 3.1)"
  set logscale y
  unset logscale x
  set format x "%g"
  set xlabel "impact k [1]"
  set ylabel "|t_k^h - t_k| [s]"
  set xrange [*:*] noextend
  set bmargin 7
  set key below maxrows 3 nobox font ",9" title " "
  plot for [i = 2:4] data('zeno_k_'.i) skip 1 using 1:($1 > 1 ? abs($3) : NaN) with points pt 7 ps 0.8 \
         lc rgb (i == 2 ? direct : i == 3 ? mj : located) title sprintf("h = 10^{-%d} s", i), \
       for [i = 2:4] data('zeno_k_'.i) skip 1 using 1:4 with lines lw 2 \
         lc rgb (i == 2 ? direct : i == 3 ? mj : located) title sprintf("h A_k, h = 10^{-%d} s", i)
  set title "(b) sup-norm error on the grid (EA Theorem 3.2; EA Conjecture 3.5 for moreau\\_jean)"
  set logscale xy
  set xrange [*:*] noextend
  set autoscale y
  set format x "10^{%T}"
  set xlabel "time step h [s]"
  set ylabel "max_l |u^l - u(t_l)| [m]"
  set key below maxrows 2 nobox font ",9" title " "
  plot data('zeno') skip 1 using 1:2 with points pt 7 lc rgb direct title "direct", \
       '' skip 1 using 1:3 with lines lw 2 lc rgb direct title "bound (EA Theorem 3.2)", \
       '' skip 1 using 1:4 with points pt 6 lc rgb mj title "moreau\\_jean", \
       '' skip 1 using 1:5 with lines lw 2 dt 2 lc rgb mj title "EA Conjecture 3.5"
  set title "(c) rest time of direct against the Zeno time (EA Theorem 3.3, C12)"
  set ylabel "|s_K - t_∞| [s]"
  plot data('zeno') skip 1 using 1:6 with points pt 7 lc rgb direct title "direct", \
       '' skip 1 using 1:7 with lines lw 2 lc rgb direct title "bound h (max(K_{max}, 2Σ_{K_{max}} + (1 + 2 S_e(K_{max})) / (1 - e)))", \
       '' skip 1 using 1:(2.5 * $1 * log(2 * V / (g * $1)) / log(1 / e)) with lines dt 2 lc rgb grey title "2.5 h ln(2V/(gh)) / ln(1/e)"
  set title "(d) impacts before rest, against K_{max} (EA Theorem 3.3)"
  unset logscale y
  set format y "%g"
  set ylabel "impacts [1]"
  plot data('zeno') skip 1 using 1:8 with points pt 7 lc rgb direct title "direct, K", \
       '' skip 1 using 1:9 with lines lw 2 lc rgb bound title "K_{max} = floor(ln(2V_1/(gh)) / ln(1/e)) + 1"
  unset multiplot
  set bmargin

  # ---- Statement 4 ----
  if (format eq "png") {
    set terminal pngcairo size 800,560 font ",10"
    set output 'figures/error_analysis_no_cor.png'
  } else {
    set terminal svg size 800,560 font ",10" dynamic
    set output 'figures/error_analysis_no_cor.svg'
  }
  set title "EA Statement 4 (no COR): f = 0, u^0 = π m, v^0 = -1 m/s, T = 10 s, elastic reference"
  set logscale xy
  set xrange [*:*] noextend
  set autoscale y
  set format y "10^{%T}"
  set xlabel "time step h [s]"
  set ylabel "error [m]"
  set key below maxrows 2 nobox font ",9" title " "
  plot data('no_cor') skip 1 using 1:3 with points pt 7 lc rgb direct title "direct: |u^n - u(T)|", \
       '' skip 1 using 1:4 with points pt 1 ps 1.3 lc rgb bound title "lower bound 2 min(θ, 1 - θ) V (T - t*) (EA Prop. 4.2)", \
       '' skip 1 using 1:5 with points pt 6 lc rgb mj title "moreau\\_jean: max_l |u^l - u(t_l)|", \
       '' skip 1 using 1:6 with lines lw 2 lc rgb mj title "bound 2 V h (EA Lemma 2.3, e = 1)"

  # ---- direct_located ----
  if (format eq "png") {
    set terminal pngcairo size 1300,1000 font ",10"
    set output 'figures/error_analysis_located.png'
  } else {
    set terminal svg size 1300,1000 font ",10" dynamic
    set output 'figures/error_analysis_located.svg'
  }
  set multiplot layout 2,2 title "Beyond order one: direct\\_located (impact located inside its step) against direct and moreau\\_jean"
  set ylabel "max_l |u^l - u(t_l)| [m]"
  set xrange [*:*] noextend
  set autoscale y
  set key below horizontal nobox font ",9" title " "
  do for [s = 0:3] {
    set title (s == 0 ? "(a) Figure 3, no COR (f = 0, impact on the grid)" : \
               s == 1 ? "(b) Figure 3, COR 0.75" : \
               s == 2 ? "(c) Figure 4, COR 0.75 (Zeno at 7.0026 s)" : \
                        "(d) vibrating table, period 1 (f(t), e = 0.5)")
    plot data('located') skip 1 using ($1 == s ? $2 : NaN):($3 > 1e-17 ? $3 : 1e-17) with linespoints pt 7 lc rgb located title "direct\\_located", \
         '' skip 1 using ($1 == s ? $2 : NaN):4 with linespoints pt 5 lc rgb direct title "direct (5-1)", \
         '' skip 1 using ($1 == s ? $2 : NaN):5 with linespoints pt 6 lc rgb mj title "moreau\\_jean"
  }
  unset multiplot
}

# ---- The campaign: measured / bound of every proved bound, every run (PNG only: 5e4 points) ----
set terminal pngcairo size 1300,1150 font ",10"
set output 'figures/error_analysis_campaign.png'
set multiplot layout 2,2 title "The campaign: 4800 random scenes x 4 schemes; measured / bound of the error analysis's (EA) proved bounds in every run (<= 1: the bound holds)"
set logscale xy
set xrange [*:*] noextend
set autoscale y
set format x "10^{%T}"
set format y "10^{%T}"
set xlabel "time step h [s]"
set ylabel "measured / bound [1]"
set bmargin 12
set key below maxrows 9 nobox font ",8" title " "
is(c) = strcol(1) eq c
# Per panel: the checks (campaign.csv's names) and what each measures. A ratio of exactly 0 (an
# error of 0: exact in that run) cannot be drawn on the log axis; the key counts those runs.
s1 = "s1.direct.forced_u s1.moreau_jean.forced_u s1.fb_newton.forced_u s1.fb_newton.constant_u s1.fb_newton.constant_v"
t1 = "'direct, f(t): u (EA Lemma 1.2)' 'moreau\\_jean, f(t): u (EA Lemma 1.2)' 'fb\\_newton, f(t): u (EA Lemma 1.2)' 'fb\\_newton, constant f: u (EA Lemma 1.3)' 'fb\\_newton, constant f: v (EA Lemma 1.3)'"
s2 = "s2.direct.du s2.direct.dv s2.direct.time s2.moreau_jean.du s2.moreau_jean.dv s2.moreau_jean.sigma s2.direct.sup_single s2.moreau_jean.sup_single"
t2 = "'direct: u (EA Lemma 2.1)' 'direct: v (EA Lemma 2.1)' 'direct: impact time (EA Lemma 2.1)' 'moreau\\_jean: u (EA Lemma 2.3)' 'moreau\\_jean: v (EA Lemma 2.3)' 'moreau\\_jean: first active step {/Symbol s} (EA Lemma 2.3)' 'direct: sup of u, one impact' 'moreau\\_jean: sup of u, one impact'"
s3 = "s3.direct.timing s3.direct.speed s3.direct.sup s3.direct.rest s3.direct.impacts"
t3 = "'impact times (EA Theorem 3.1)' 'impact speeds (EA Theorem 3.1)' 'sup of u (EA Theorem 3.2)' 'rest time (EA Theorem 3.3)' 'impacts before rest (EA Theorem 3.3)'"
s4 = "s4.direct.effective_cor s4.direct.lower_bound s4.fb_newton.effective_cor s4.fb_newton.lower_bound"
t4 = "'direct: effective COR - |1 - 2{/Symbol q}| (EA Lemma 2.2)' 'direct: bound / error (EA Prop. 4.2)' 'fb\\_newton: effective COR (EA Lemma 2.2)' 'fb\\_newton: bound / error (EA Prop. 4.2)'"
# Distinct markers, large and open under small and filled, so that equal ratios (the three schemes
# fly alike in (a)) stay visible.
marker(i) = word("6 4 7 8 12 2 1 10", i) + 0
msize(i) = word("1.6 1.1 0.5 0.9 0.9 0.7 0.7 0.9", i) + 0
do for [p = 1:4] {
  names = p == 1 ? s1 : p == 2 ? s2 : p == 3 ? s3 : s4
  titles = p == 1 ? t1 : p == 2 ? t2 : p == 3 ? t3 : t4
  set title (p == 1 ? "(a) EA Statement 1, free flight: error / bound" : \
             p == 2 ? "(b) EA Statement 2, one impact: error / bound" : \
             p == 3 ? "(c) EA Statement 3, many impacts (direct): error / bound" : \
                      "(d) EA Statement 4, no COR: error / bound, and lower bound / error")
  keys = ""
  do for [i = 1:words(names)] {
    stats data('campaign') skip 1 using (is(word(names, i)) ? 1 : 0):(is(word(names, i)) && $7 == 0 ? 1 : 0) nooutput
    keys = keys.sprintf(" '%s: %d runs%s'", word(titles, i), STATS_sum_x, STATS_sum_y > 0 ? sprintf(", %d at 0 (not drawn)", STATS_sum_y) : "")
  }
  plot for [i = 1:words(names)] data('campaign') skip 1 using (is(word(names, i)) ? $3 : NaN):7 \
         with points pt marker(i) ps msize(i) lc i title word(keys, i), \
       1 with lines lw 2 lc rgb bound title "bound (ratio 1)"
}
unset multiplot
