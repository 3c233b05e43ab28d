# Throughput. Reads results/performance/ (exp_performance), writes performance.{png,svg} to `out`
# (results/figures: `make refresh-timing-figures` copies them to figures/): (a) ns per step of
# each time-stepper in each phase of a motion (performance_phases.hpp): the bare loop of (5-1),
# simulate() and `impact run`, against the targets (1.5x the stepper's free-flight cost; impact
# run: 1.5x the bare loop); (b) the ensemble's particle-steps per second for each vector
# instruction set, against its targets. The title names the processor (processor.txt).
# Usage: gnuplot -e "results='results/performance'; out='results/figures'" \
#          experiments/performance/plot.gp
if (!exists("results")) results = 'results/performance'
if (!exists("out")) out = 'results/figures'
set datafile separator ','
processor = system("cat '".results."/processor.txt'")
phases = results.'/plot_phases.csv'
# (a)'s axis starts at the decade below the least bar of the bare loop and of impact run. simulate()
# at rest or in chatter steps one period and hands the repeats to its observer, which costs ~1e-5
# ns per step of the run: those bars would run down 5 decades, so they are marked by a triangle on
# the axis instead, with their value.
stats phases skip 1 using 2 nooutput
least = STATS_min
stats phases skip 1 using 4 nooutput
least = STATS_min < least ? STATS_min : least
axis_bottom = 10**floor(log10(least))

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1500,700 font ",10"
    set output out.'/performance.png'
  } else {
    set terminal svg size 1500,700 font ",10" dynamic
    set output out.'/performance.svg'
  }
  set multiplot layout 1,2 title "Throughput on one core of an ".processor. \
      " (best of 5 repetitions, CPU time)" noenhanced

  set title "(a) time per step by phase, 1e8 steps (fb\\_newton 1e7); at rest and in chatter a run takes\none period and hands the rest to its observer (simulate(): a no-op, impact run: a row check)"
  # Each key at the bottom of the figure, under its panel and its slanted bar names.
  set bmargin 15
  set style data histogram
  set style histogram clustered gap 1
  set style fill solid 0.8 border -1
  set boxwidth 0.9
  set logscale y
  set yrange [axis_bottom:*]
  set format y "10^{%L}"
  set ylabel "CPU time per step [ns]"
  # no xlabel: the bars are named by method and phase of the motion
  unset xlabel
  set xtics rotate by -35 font ",8" noenhanced
  set grid ytics
  set key at screen 0.25, screen 0.01 center bottom horizontal maxrows 3 width -4 nobox
  plot phases skip 1 using 2:xtic(1) lc rgb "#999999" \
           title "bare loop of (5-1) (direct)", \
       '' skip 1 using 3 lc rgb "#0072B2" title "simulate(), output off", \
       '' skip 1 using 4 lc rgb "#E69F00" title "impact run, CSV of 1e4 rows", \
       '' skip 1 using ($0):5 with points pt 2 ps 2 lc rgb "#D55E00" \
           title "target: 1.5 x the method's free flight", \
       '' skip 1 using ($0 + 0.27):6 with points pt 6 ps 1.5 lc rgb "#D55E00" \
           title "target of impact run: 1.5 x bare loop", \
       '' skip 1 using ($0):($3 < axis_bottom ? 1.4 * axis_bottom : NaN) with points pt 11 ps 1.6 \
           lc rgb "#0072B2" title "simulate() below the axis (value printed): one period, then repeats", \
       '' skip 1 using ($0):($3 < axis_bottom ? 2.6 * axis_bottom : NaN):(sprintf("%.0e", $3)) \
           with labels rotate by 90 left font ",8" tc rgb "#0072B2" notitle

  set title "(b) ensemble: particles stepped together on vector lanes (960 particles)"
  set ylabel "particle-steps per second [1/s]"
  set autoscale y
  set key at screen 0.75, screen 0.01 center bottom horizontal maxrows 3 nobox
  plot results.'/plot_ensemble.csv' skip 1 using 2:xtic(1) lc rgb "#009E73" \
           title "T = 10 s sweep from the drop", \
       '' skip 1 using 3 lc rgb "#999999" title "settled at rest", \
       '' skip 1 using ($0):4 with points pt 2 ps 2 lc rgb "#D55E00" \
           title "target (direct: 1.5e9 AVX-512, 1e9 AVX2)"
  unset multiplot
  set bmargin
}
