# Throughput. Reads results/performance/ (exp_performance), writes
# figures/performance.{png,svg}: (a) ns per step of each time-stepper on the paper's scenes, in
# the benchmark (simulate(), output off) and through `impact run` (a process, a scene file, CSV
# decimated to ~1e4 rows), against the throughput targets; (b) the ensemble's particle-steps per
# second for each vector instruction set, against the target of 1e9.
# Usage: gnuplot -e "results='results/performance'" experiments/performance/plot.gp
if (!exists("results")) results = 'results/performance'
set datafile separator ','

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1500,600 font ",10"
    set output 'figures/performance.png'
  } else {
    set terminal svg size 1500,600 font ",10" dynamic
    set output 'figures/performance.svg'
  }
  set multiplot layout 1,2 title "Throughput on one core (best of 5 repetitions, CPU time)"

  set title "(a) time per step over T = 10 s: simulate() 1e7 steps, impact run 1e8 (fb\\_newton: 1e6, 1e7)"
  set style data histogram
  set style histogram clustered gap 1
  set style fill solid 0.8 border -1
  set boxwidth 0.9
  set logscale y
  set yrange [0.5:200]
  set ylabel "CPU time per step [ns]"
  set xtics rotate by -35 font ",8" noenhanced
  set grid ytics
  set key top left
  plot results.'/plot_steps.csv' skip 1 using 2:xtic(1) lc rgb "#0072B2" title "simulate(), output off", \
       '' skip 1 using 3 lc rgb "#E69F00" title "impact run, decimated CSV", \
       '' skip 1 using ($0):4 with points pt 2 ps 2 lc rgb "#D55E00" title "target of issue 4"

  set title "(b) ensemble: particles stepped together on vector lanes (960 particles)"
  set ylabel "particle-steps per second"
  set yrange [1e7:1e10]
  set format y "10^{%L}"
  plot results.'/plot_ensemble.csv' skip 1 using 2:xtic(1) lc rgb "#009E73" \
           title "T = 10 s sweep from the drop", \
       '' skip 1 using 3 lc rgb "#999999" title "settled at rest: v subnormal on half the lanes", \
       1e9 with lines lw 2 dt 2 lc rgb "#D55E00" title "target 10^9 (direct)"
  unset multiplot
}
