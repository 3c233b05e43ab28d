# The impact oscillator u'' = -u - cos(omega t) + N, u >= phi = -sigma, COR r = 0.8. Five figures:
#  impact_oscillator: bifurcation diagrams (impact speed after a transient) in sigma (omega = 2.8)
#    and in omega (sigma = -0.5) from the exact-flight reference, swept up and down, with the
#    closed-form period-one branches, their thresholds and the branch runs drawn over them;
#  impact_oscillator_orbit: the acceptance run settling on the period-one orbit, impact by impact;
#  impact_oscillator_grazing: the first impact speed of a grazing pass against the square-root law;
#  impact_oscillator_chatter: a chatter into a rest and its lift-off; the accumulation time
#    against 2 v0/(a (1 - r));
#  impact_oscillator_work_precision (CPU times: written to `timing`): error against CPU time of
#    every method that takes a force of the state, on a periodic and a chaotic scene, and the
#    chaotic scene's Lyapunov separation with the horizon marked.
# Usage: gnuplot -e "results='results/impact_oscillator'; timing='results/figures'" plot.gp
if (!exists("results")) results = 'results/impact_oscillator'
if (!exists("timing")) timing = 'results/figures'
set datafile separator ','
load results.'/values.gp'

blue = "#0072B2"; orange = "#E69F00"; green = "#009E73"; red = "#D55E00"; pink = "#CC79A7"
gray = "#999999"
is(col, text) = strcol(col) eq text
impact_of(direction) = (is(1, direction) && is(3, "impact")) ? $5 : NaN
lift_of(direction) = (is(1, direction) && is(3, "lift")) ? 0 : NaN
runner(name, col) = is(1, name) ? column(col) : NaN

# A vertical line at x over the whole panel (arrows stay out of the key).
vline(n, x, style) = sprintf("set arrow %d from %.17g, graph 0 to %.17g, graph 1 nohead %s", n, x, x, style)

do for [format in "png pdf"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,1100 font ",10"
    set output 'figures/impact_oscillator.png'
  } else {
    set terminal pdfcairo size 8.7in,7.4in font ",7"
    set output 'figures/impact_oscillator.pdf'
  }
  set multiplot layout 2,1 title "Impact oscillator x'' + x = cos({/Symbol w}t), x <= {/Symbol s}, r = 0.8: impact speed after 100 forcing periods (exact-flight reference), 40 periods kept"
  set grid
  set key below maxrows 3 nobox
  set ylabel "impact speed V [1]"
  set autoscale xy
  set offsets graph 0, graph 0, graph 0.05, graph 0
  # (a) sigma
  eval vline(1, thresholds_sigma_saddle_node, "lw 1.5 dt 2 lc rgb 'black'")
  eval vline(2, thresholds_sigma_period_doubling, "lw 1.5 dt 3 lc rgb 'black'")
  eval vline(3, thresholds_sigma_grazing, "lw 1 dt 4 lc rgb '".gray."'")
  set xlabel "wall position {/Symbol s} = -{/Symbol f} [1]"
  set title sprintf("(a) {/Symbol w} = 2.8: saddle-node {/Symbol s}_{sn} = %.6f (dashed), period doubling {/Symbol s}_{pd} = %.6f (dotted), grazing |{/Symbol g}| = %.6f (gray)", thresholds_sigma_saddle_node, thresholds_sigma_period_doubling, thresholds_sigma_grazing)
  plot results.'/diagram_sigma.csv' skip 1 using 2:(impact_of("down")) with points pt 7 ps 0.15 lc rgb blue title "impacts, sweep down", \
       results.'/diagram_sigma.csv' skip 1 using 2:(impact_of("up")) with points pt 7 ps 0.15 lc rgb orange title "impacts, sweep up (from rest at {/Symbol s} = -1.9)", \
       results.'/diagram_sigma.csv' skip 1 using 2:(lift_of("up")) with points pt 1 ps 0.6 lc rgb red title "lift-off after a rest", \
       results.'/branches_sigma.csv' skip 1 using 1:2 with lines lw 1.5 lc rgb "black" title "period one (closed form), stable", \
       results.'/branches_sigma.csv' skip 1 using 1:3 with lines lw 1.5 dt 2 lc rgb "black" title "period one, unstable", \
       results.'/branches_sigma.csv' skip 1 using 1:4 with lines lw 1 dt 3 lc rgb gray title "the saddle (the other root)", \
       results.'/branch_sigma.csv' skip 1 using 2:(runner("reference", 7)) with points pt 6 ps 1.2 lc rgb green title "branch runs, reference", \
       results.'/branch_sigma.csv' skip 1 using 2:(runner("event_driven", 7)) with points pt 2 ps 1.5 lc rgb pink title "branch runs, event\\_driven"
  # (b) omega
  eval vline(1, thresholds_omega_saddle_node, "lw 1.5 dt 2 lc rgb 'black'")
  eval vline(2, thresholds_omega_period_doubling, "lw 1.5 dt 3 lc rgb 'black'")
  unset arrow 3
  set xlabel "forcing frequency {/Symbol w} [1]"
  set title sprintf("(b) {/Symbol s} = -0.5: saddle-node {/Symbol w}_{sn} = %.6f (dashed), period doubling {/Symbol w}_{pd} = %.6f (dotted)", thresholds_omega_saddle_node, thresholds_omega_period_doubling)
  plot results.'/diagram_omega.csv' skip 1 using 2:(impact_of("down")) with points pt 7 ps 0.15 lc rgb blue title "impacts, sweep down", \
       results.'/diagram_omega.csv' skip 1 using 2:(impact_of("up")) with points pt 7 ps 0.15 lc rgb orange title "impacts, sweep up", \
       results.'/diagram_omega.csv' skip 1 using 2:(lift_of("up")) with points pt 1 ps 0.6 lc rgb red title "lift-off after a rest, up", \
       results.'/diagram_omega.csv' skip 1 using 2:(lift_of("down")) with points pt 2 ps 0.6 lc rgb red title "lift-off after a rest, down", \
       results.'/branches_omega.csv' skip 1 using 1:2 with lines lw 1.5 lc rgb "black" title "period one, stable", \
       results.'/branches_omega.csv' skip 1 using 1:3 with lines lw 1.5 dt 2 lc rgb "black" title "period one, unstable", \
       results.'/branches_omega.csv' skip 1 using 1:4 with lines lw 1 dt 3 lc rgb gray title "the saddle", \
       results.'/branch_omega.csv' skip 1 using 2:(runner("reference", 7)) with points pt 6 ps 1.2 lc rgb green title "branch runs, reference", \
       results.'/branch_omega.csv' skip 1 using 2:(runner("event_driven", 7)) with points pt 2 ps 1.5 lc rgb pink title "branch runs, event\\_driven"
  unset multiplot
  unset arrow
  unset offsets
}

# The acceptance run, impact by impact: its distance from the closed-form orbit.
period = 2 * pi / omega
phase_gap(t) = abs(t - orbit_phase - period * floor((t - orbit_phase) / period + 0.5))
do for [format in "png pdf"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,520 font ",10"
    set output 'figures/impact_oscillator_orbit.png'
  } else {
    set terminal pdfcairo size 8.7in,3.5in font ",7"
    set output 'figures/impact_oscillator_orbit.pdf'
  }
  set multiplot layout 1,2 title sprintf("From u_0 = 1, v_0 = 0 ({/Symbol w} = 2.8, r = 0.8, {/Symbol f} = 0.5) onto the period-one orbit: V = %.13f, phase %.13f", orbit_V, orbit_phase)
  set grid
  set logscale y
  set format y "10^{%L}"
  set autoscale xy
  set xlabel "impact number k [1]"
  set key below nobox
  set title "(a) impact speed: |V_k - V|, the closed form's V"
  set ylabel "|V_k - V| [1]"
  plot results.'/acceptance_impacts.csv' skip 1 using 2:(abs(runner("reference", 4) - orbit_V)) with points pt 6 lc rgb blue title "exact-flight reference", \
       results.'/acceptance_impacts.csv' skip 1 using 2:(abs(runner("event_driven", 4) - orbit_V)) with points pt 2 lc rgb orange title "event\\_driven (rk8pd, rtol 1e-12)", \
       results.'/acceptance_impacts.csv' skip 1 using 2:(runner("reference", 2) > 0 ? 0.8**column(2) : NaN) with lines dt 2 lc rgb "black" title "0.8^k = |{/Symbol l}|^k"
  set title "(b) impact phase: distance of t_k mod 2{/Symbol p}/{/Symbol w} from the closed form's"
  set ylabel "phase error [1]"
  plot results.'/acceptance_impacts.csv' skip 1 using 2:(phase_gap(runner("reference", 3))) with points pt 6 lc rgb blue title "exact-flight reference", \
       results.'/acceptance_impacts.csv' skip 1 using 2:(phase_gap(runner("event_driven", 3))) with points pt 2 lc rgb orange title "event\\_driven"
  unset multiplot
  unset logscale y
  set format y "% h"
}

do for [format in "png pdf"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,520 font ",10"
    set output 'figures/impact_oscillator_grazing.png'
  } else {
    set terminal pdfcairo size 8.7in,3.5in font ",7"
    set output 'figures/impact_oscillator_grazing.pdf'
  }
  set multiplot layout 1,2 title sprintf("Grazing ({/Symbol w} = 2.8): a pass that would reach {/Symbol d} past the wall hits with V = (2a{/Symbol d})^{1/2} (1 + O({/Symbol d}^{1/2})); fitted exponent %.9f over {/Symbol d} = 10^{-10} ... 10^{-6}", grazing_exponent)
  set grid
  set logscale xy
  set format x "10^{%L}"
  set format y "10^{%L}"
  set autoscale xy
  set xlabel "penetration of the free orbit {/Symbol d} [1]"
  set key below nobox
  set title "(a) first impact speed of the pass, and the period-one orbit's at {/Symbol s} = |{/Symbol g}| - {/Symbol d}"
  set ylabel "impact speed V [1]"
  plot results.'/grazing.csv' skip 1 using 1:2 with points pt 6 lc rgb blue title "first impact, exact-flight reference", \
       results.'/grazing.csv' skip 1 using 1:4 with points pt 2 ps 1.3 lc rgb orange title "first impact, event\\_driven", \
       results.'/grazing.csv' skip 1 using 1:(grazing_sqrt_2a * sqrt($1)) with lines lc rgb "black" title "(2a{/Symbol d})^{1/2}, a = 1 + |{/Symbol g}|", \
       results.'/grazing.csv' skip 1 using 1:5 with linespoints pt 4 lc rgb green title sprintf("period-one orbit (closed form): exponent %.6f", grazing_orbit_exponent)
  set title "(b) against the exact first impact speed {/Symbol w} ({/Symbol d} (2|{/Symbol g}| - {/Symbol d}))^{1/2}"
  set ylabel "|V / exact - 1| [1]"
  plot results.'/grazing.csv' skip 1 using 1:(abs($2 / $3 - 1)) with points pt 6 lc rgb blue title "exact-flight reference", \
       results.'/grazing.csv' skip 1 using 1:(abs($4 / $3 - 1)) with points pt 2 ps 1.3 lc rgb orange title "event\\_driven"
  unset multiplot
  unset logscale
  set format x "% h"
  set format y "% h"
}

do for [format in "png pdf"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,520 font ",10"
    set output 'figures/impact_oscillator_chatter.png'
  } else {
    set terminal pdfcairo size 8.7in,3.5in font ",7"
    set output 'figures/impact_oscillator_chatter.pdf'
  }
  set multiplot layout 1,2 title "Chatter and sticking ({/Symbol w} = 2.8, r = 0.8, {/Symbol f} = 0.5): impacts accumulate after 2 v_0 / (a (1 - r)), v_0 the take-off speed, a the push"
  set grid
  set key below nobox
  set xlabel "t [1]"
  set ylabel "u - {/Symbol f} [1]"
  # The chatter's bounces shrink geometrically: a log axis, from 1e-9 of the highest one up.
  stats results.'/sticking_trajectory.csv' skip 1 using ($1 <= 1.6 * chatter_sticking_lift_off ? $2 - 0.5 : NaN) nooutput
  set logscale y
  set format y "10^{%L}"
  set xrange [* : 1.6 * chatter_sticking_lift_off]
  set yrange [STATS_max * 1e-9 : STATS_max * 3]
  eval vline(1, chatter_sticking_t_inf, "dt 2 lc rgb 'black'")
  eval vline(2, chatter_sticking_lift_off, "dt 3 lc rgb 'black'")
  set title sprintf("(a) from the wall with v_0 = %.2f: rest from t_{/Symbol \245} = %.6f, lift-off at acos(-{/Symbol f})/{/Symbol w} = %.6f", chatter_sticking_v0, chatter_sticking_t_inf, chatter_sticking_lift_off)
  events = results.'/sticking_events.csv'
  bottom = STATS_max * 3e-9
  plot results.'/sticking_trajectory.csv' skip 1 using 1:($2 - 0.5 > 0 ? $2 - 0.5 : NaN) with lines lc rgb blue title "exact-flight reference", \
       events skip 1 using (is(1, "reference") && is(2, "impact") ? $3 : NaN):(bottom) with points pt 6 ps 0.8 lc rgb blue title "its impacts (drawn at the bottom)", \
       events skip 1 using (is(1, "event_driven") && is(2, "impact") ? $3 : NaN):(2 * bottom) with points pt 2 ps 0.8 lc rgb orange title "event\\_driven's impacts", \
       events skip 1 using (is(2, "stick") ? $3 : NaN):(4 * bottom) with points pt 9 ps 1.5 lc rgb red title "rest (both)", \
       events skip 1 using (is(2, "lift") ? $3 : NaN):(4 * bottom) with points pt 11 ps 1.5 lc rgb green title "lift-off (both)"
  set autoscale xy
  unset arrow
  set logscale xy
  set format x "10^{%L}"
  set format y "10^{%L}"
  set xlabel "take-off speed v_0 [1]"
  set ylabel "|relative deviation of t_{/Symbol \245} - t_0| [1]"
  set title "(b) the accumulation time against 2 v_0/(a_0 (1 - r)), a_0 = {/Symbol f} + cos({/Symbol w}t_0)"
  plot results.'/chatter.csv' skip 1 using ($1 == 0 ? $2 : NaN):(abs($5)) with linespoints pt 6 lc rgb blue title "{/Symbol w}t_0 = 0 (a' = 0): O(v_0^2)", \
       results.'/chatter.csv' skip 1 using ($1 == 1 ? $2 : NaN):(abs($5)) with linespoints pt 4 lc rgb orange title "{/Symbol w}t_0 = 1: O(v_0)", \
       results.'/chatter.csv' skip 1 using ($1 == 1 ? $2 : NaN):(abs($6)) with linespoints pt 2 lc rgb green title "{/Symbol w}t_0 = 1 with the factor 1 - (2/3) a' v_0/(a_0^2 (1 - r)): O(v_0^2)"
  unset multiplot
  unset logscale
  set format x "% h"
  set format y "% h"
}

# Work against precision: CPU times of this machine.
wp = results.'/work_precision.csv'
pick(scene, method) = (is(1, scene) && is(2, method)) ? $7 : NaN
if (!exists("processor")) processor = "this machine"
do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1500,520 font ",10"
    set output timing.'/impact_oscillator_work_precision.png'
  } else {
    set terminal svg size 1500,520 dynamic font ",10"
    set output timing.'/impact_oscillator_work_precision.svg'
  }
  set multiplot layout 1,3 title "Work against precision on the impact oscillator (-u - cos(2.8 t), a force of the state) against the exact-flight reference\nCPU times on ".processor."; h = 0.1 ... 1e-4, event_driven rtol = atol = 1e-3 ... 1e-11" noenhanced
  set grid
  set logscale xy
  set format x "10^{%L}"
  set format y "10^{%L}"
  set autoscale xy
  set xlabel "CPU time of the solve [s]"
  set ylabel "max_l |u^l - u(t_l)| [1]"
  set key below nobox
  do for [scene in "periodic chaotic"] {
    set title sprintf("(%s) %s scene, T = %g", scene eq "periodic" ? "a" : "b", scene, scene eq "periodic" ? work_precision_periodic_T : work_precision_chaotic_T)
    plot wp skip 1 using (pick(scene, "direct")):5 with linespoints pt 7 lc rgb blue title "direct", \
         wp skip 1 using (pick(scene, "moreau_jean")):5 with linespoints pt 5 lc rgb orange title "moreau\\_jean", \
         wp skip 1 using (pick(scene, "event_driven")):5 with points pt 9 ps 1.3 lc rgb green title "event\\_driven"
  }
  set logscale y
  unset logscale x
  set format x "% h"
  set xlabel "t [1]"
  set ylabel "distance of two runs 1e-10 apart [1]"
  eval vline(1, work_precision_chaotic_T, "lw 2 lc rgb '".red."'")
  set title sprintf("(c) chaotic scene: {/Symbol l} = %.3f, 1/{/Symbol l} = %.2f > T = %g (red)", work_precision_chaotic_lyapunov, work_precision_chaotic_lyapunov_time, work_precision_chaotic_T)
  plot results.'/lyapunov.csv' skip 1 using 1:($2 > 0 ? $2 : NaN) with lines lc rgb gray title "distance of two runs 1e-10 apart", \
       results.'/lyapunov.csv' skip 1 using 1:3 with lines lw 2 lc rgb blue title "its running maximum, fitted up to 1e-3"
  unset multiplot
  unset arrow
}
