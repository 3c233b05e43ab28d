# Lemma 3 (Section 4): measured / bound for the 144 runs of the sweep (direct scheme, no COR,
# phi = 0, T = 2 s), ordered by f, then u0, then v0, then h (colour). A ratio above 1 breaks the
# bound; a ratio of exactly 0 is drawn at the bottom of the axis.
# Usage: gnuplot -e "results='results/lemma3'" experiments/lemma3/plot.gp
if (!exists("results")) results = 'results/lemma3'
set datafile separator ','
file = results.'/runs.csv'

hs = "0.1 0.01 0.001 0.0001"
colors = "#1b9e77 #d95f02 #7570b3 #e7298a"
is_h(h, k) = abs(h - word(hs, k) + 0) < 1e-12
at_least(x) = x < 1e-10 ? 1e-10 : x
pick(h, k, y) = is_h(h, k) ? y : NaN

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1200,900 font ",10"
    set output 'figures/lemma3.png'
  } else {
    set terminal svg size 1200,900 font ",10" dynamic
    set output 'figures/lemma3.svg'
  }
  set multiplot layout 2,2 title "Lemma 3: measured / bound over 4 h x 4 f x 3 u_0 x 3 v_0 = 144 runs (direct scheme, T = 2 s)"
  set grid
  set xrange [0:145]  # fixed range: the 144 runs, numbered 1..144, in four blocks of f
  set xtics ("f = -9.80665 m/s^2" 18.5, "f = -1" 54.5, "f = 0" 90.5, "f = +1" 126.5)
  set arrow 1 from 36.5, graph 0 to 36.5, graph 1 nohead lc rgb "gray"
  set arrow 2 from 72.5, graph 0 to 72.5, graph 1 nohead lc rgb "gray"
  set arrow 3 from 108.5, graph 0 to 108.5, graph 1 nohead lc rgb "gray"
  set xlabel "run (within each f: u_0 = 0, 1, 5 m; v_0 = -3, -0.5, 2 m/s; h) [1]"
  set logscale y 10
  set format y "10^{%L}"
  set yrange [1e-10:*]  # fixed range: a ratio of exactly 0 is drawn at 1e-10, the axis bottom
  set bmargin 8
  set key below maxrows 3 nobox title " "

  set ylabel "max_l |v^l| / V [1]"
  set title "(a) velocity: V = sqrt((2E^0 + 2|f||u^0| + |f|T)(1 + |f|T e^{|f|T}))"
  plot for [k=1:4] file using 1:(pick($2, k, at_least($15))) with points pt 7 ps 0.8 \
         lc rgb word(colors, k) title "h = ".word(hs, k)." s", \
       1 with lines lc rgb "black" lw 1.5 dt 2 title "bound"

  # The colour is h, the marker the bound: both keyed (the open markers used to be unkeyed).
  set ylabel "max_l |u^l| / bound [1]"
  set title "(b) displacement: filled |u^0| + (T/2) V (printed), open |u^0| + T V (corrected)"
  plot for [k=1:4] file using 1:(pick($2, k, at_least($16))) with points pt 7 ps 0.8 \
         lc rgb word(colors, k) title "h = ".word(hs, k)." s", \
       for [k=1:4] file using 1:(pick($2, k, at_least($17))) with points pt 6 ps 1.2 \
         lc rgb word(colors, k) notitle, \
       NaN with points pt 7 ps 0.8 lc rgb "black" title "printed: |u^0| + (T/2) V", \
       NaN with points pt 6 ps 1.2 lc rgb "black" title "corrected: |u^0| + T V", \
       1 with lines lc rgb "black" lw 1.5 dt 2 title "bound"

  set ylabel "h sum_l N^l / (V - v^0) [1]"
  set title "(c) total impulse: the claim after (4-9), h sum N^l <= V - v^0 (0 drawn at 10^{-10})"
  plot for [k=1:4] file using 1:(pick($2, k, at_least($18))) with points pt 7 ps 0.8 \
         lc rgb word(colors, k) title "h = ".word(hs, k)." s", \
       1 with lines lc rgb "black" lw 1.5 dt 2 title "bound"

  unset logscale y
  set format y "% h"
  set autoscale y
  set offsets 0, 0, graph 0.05, graph 0.05
  set ylabel "max_l (E^{l+1} - E^l) / round-off tolerance [1]"
  set title "(d) energy inequality E^{l+1} <= E^l (4-6): largest increase per run"
  plot for [k=1:4] file using 1:(pick($2, k, $21 > 0 ? $21 : 0)) with points pt 7 ps 0.8 \
         lc rgb word(colors, k) title "h = ".word(hs, k)." s", \
       1 with lines lc rgb "black" lw 1.5 dt 2 title "tolerance"
  unset multiplot
  unset offsets
  set bmargin
}

# Lemma 3 with f(t) = f + a sin(omega t + phase): measured / bound for every run of the forcing
# sweep (results/lemma3/forcing_runs.csv, src/analysis/lemma3/lemma3_forcing.hpp), one column per reading
# of |f|, the runs spread across each column in sweep order; direct and fb_newton in two colours.
forcing = results.'/forcing_runs.csv'
set autoscale
unset logscale
stats forcing using 1 nooutput
runs = STATS_max
readings = "sup mean rms sup_f0 mean_f0 rms_f0 constant frozen"
spread(k) = k + 0.7 * ($1 / runs - 0.5)
# Two readings side by side in one column: the left and the right half.
spread_left(k) = k - 0.19 + 0.33 * ($1 / runs - 0.5)
spread_right(k) = k + 0.19 + 0.33 * ($1 / runs - 0.5)
is_direct(y) = strcol(2) eq "direct" ? y : NaN
is_newton(y) = strcol(2) eq "fb_newton" ? y : NaN
# The vector copy is an SVG whose runs are dots (1536 runs x 9 readings in (a) and (b)).
do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1200,1000 font ",10"
    set output 'figures/lemma3_forcing.png'
  } else {
    set terminal svg size 1200,1000 font ",10" dynamic
    set output 'figures/lemma3_forcing.svg'
  }
  # The SVG draws each run as a dot (a marker each would make it 4.8 MB).
  vector = format eq "svg"
  set multiplot layout 2,2 title sprintf("Lemma 3 with f(t) = f + a sin(omega t + phase): %d runs (direct, fb\\_newton; T = 2 s)", runs)
  set grid
  unset arrow
  set logscale y 10
  set format y "10^{%L}"
  set bmargin 7
  set key below maxrows 2 nobox title " "
  set xrange [0.4:9.6]  # fixed range: nine columns, one per reading of |f|
  set xtics rotate by 30 right ("sup" 1, "mean" 2, "rms" 3, "sup, f(0)" 4, "mean, f(0)" 5, \
             "rms, f(0)" 6, "constant f" 7, "frozen f(t_l)" 8, "proof P" 9)
  # no xlabel: the x axis names the readings of |f|, categories rather than a quantity
  set xlabel "reading of |f| in the bound (E^0 from +-F, or from f(0))"

  set autoscale y
  set ylabel "max_l |v^l| / bound [1]"
  set title "(a) velocity: V = sqrt((2E^0 + 2F|u^0| + FT)(1 + FT e^{FT})); P = |v^0| + int_0^T |f|"
  plot for [k=1:8] forcing using (spread(k)):(is_direct(column(12 + 3 * k))) with points pt (vector ? 0 : 7) ps 0.3 \
         lc rgb "#1b9e77" title (k == 1 ? "direct" : ""), \
       for [k=1:8] forcing using (spread(k)):(is_newton(column(12 + 3 * k))) with points pt (vector ? 0 : 6) ps 0.4 \
         lc rgb "#d95f02" title (k == 1 ? "fb\\_newton" : ""), \
       forcing using (spread(9)):(is_direct($39)) with points pt (vector ? 0 : 7) ps 0.3 lc rgb "#1b9e77" notitle, \
       forcing using (spread(9)):(is_newton($39)) with points pt (vector ? 0 : 6) ps 0.4 lc rgb "#d95f02" notitle, \
       1 with lines lc rgb "black" lw 1.5 dt 2 title "bound"

  # The printed and the corrected bound side by side in each column (the open markers used to
  # cover the filled ones), and the proof's bound with a marker and a key entry of its own.
  set ylabel "max_l |u^l| / bound [1]"
  set title "(b) displacement: filled |u^0| + (T/2) V (printed), open |u^0| + T V; proof: |u^0| + T P"
  plot for [k=1:8] forcing using (spread_left(k)):(column(13 + 3 * k)) with points pt (vector ? 0 : 7) ps 0.3 \
         lc rgb "#7570b3" title (k == 1 ? "printed: |u^0| + (T/2) V" : ""), \
       for [k=1:8] forcing using (spread_right(k)):(column(14 + 3 * k)) with points pt (vector ? 0 : 6) ps 0.4 \
         lc rgb "#e7298a" title (k == 1 ? "corrected: |u^0| + T V" : ""), \
       forcing using (spread(9)):40 with points pt (vector ? 0 : 4) ps 0.4 lc rgb "#66a61e" \
         title "proof: |u^0| + T P", \
       1 with lines lc rgb "black" lw 1.5 dt 2 title "bound"

  set xrange [*:*]
  set logscale x 10
  set format x "10^{%L}"
  set xtics auto norotate
  set autoscale y
  set xlabel "amplitude a [m/s^2]"
  set ylabel "max_l (E^{l+1} - E^l) [J/kg]"
  set title "(c) E^l = (v^l)^2/2 - f(t_l) u^l rises; W^l (work-corrected) never does beyond round-off"
  plot forcing using ($4 * (1 + 0.3 * ($1 / runs - 0.5))):(is_direct($43 > 0 ? $43 : NaN)) \
         with points pt (vector ? 0 : 7) ps 0.3 lc rgb "#1b9e77" title "E, direct", \
       forcing using ($4 * (1 + 0.3 * ($1 / runs - 0.5))):(is_newton($43 > 0 ? $43 : NaN)) \
         with points pt (vector ? 0 : 6) ps 0.4 lc rgb "#d95f02" title "E, fb\\_newton"

  set xlabel "omega [rad/s]"
  set ylabel "max_l |v^l| / bound [1]"
  set title "(d) velocity under three readings of |f| against omega, every run"
  plot forcing using ($5 * (1 + 0.3 * ($1 / runs - 0.5))):($15) with points pt (vector ? 0 : 7) ps 0.3 \
         lc rgb "#1b9e77" title "sup |f|", \
       forcing using ($5 * (1 + 0.3 * ($1 / runs - 0.5))):($33) with points pt (vector ? 0 : 6) ps 0.4 \
         lc rgb "#d95f02" title "constant part", \
       forcing using ($5 * (1 + 0.3 * ($1 / runs - 0.5))):($36) with points pt (vector ? 0 : 4) ps 0.4 \
         lc rgb "#7570b3" title "frozen f(t_l)", \
       1 with lines lc rgb "black" lw 1.5 dt 2 title "bound"
  unset multiplot
  unset logscale x
  set format x "% h"
  set bmargin
  set xrange [0.4:9.6]  # fixed range: nine columns, one per reading of |f|
  set xtics rotate by 30 right ("sup" 1, "mean" 2, "rms" 3, "sup, f(0)" 4, "mean, f(0)" 5, \
             "rms, f(0)" 6, "constant f" 7, "frozen f(t_l)" 8, "proof P" 9)
  set logscale y 10
  set format y "10^{%L}"
}
