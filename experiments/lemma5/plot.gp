# Lemma 5 (Section 5.1): the pairing of N_eps = S''/6 (the proof's contact force) with smooth test
# functions psi, divided by psi(t*), against eps. (a) It tends to 1/2, not to 1 as the lemma
# claims; S''/3 tends to 1. (b) The deviation from 1/2 is psi''(t*) eps^2 / (24 psi(t*)) + O(eps^4)
# (dashed). (c) Each cubic piece contributes psi(t*)/4, not the psi(t*)/2 the proof computes.
# Usage: gnuplot -e "results='results/lemma5'" experiments/lemma5/plot.gp
if (!exists("results")) results = 'results/lemma5'
names = "gaussian cos cubic exp bump"
titles = "'Gaussian' 'cos t' 'cubic' 'e^{-t}' 'C^{/Symbol \245} bump'"
colors = "#0072B2 #D55E00 #009E73 #CC79A7 #E69F00"
file(i) = results.'/pairing_'.word(names, i).'.csv'
set datafile separator ','

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1500,620 font ",10"
    set output 'figures/lemma5.png'
  } else {
    set terminal svg size 1500,620 font ",10" dynamic
    set output 'figures/lemma5.svg'
  }
  set multiplot layout 1,3 title \
      "Lemma 5: pairing of the contact force with test functions {/Symbol y}, t_* = 5"
  set grid
  set logscale x
  set xrange [*:*] noextend
  set format x "10^{%T}"
  set xlabel "{/Symbol e} [s]"
  set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
  # Every key below its panel, in a bottom margin of the same height, so that the panels line up.
  set bmargin 9
  set key below maxrows 3 nobox title " "

  set title "(a) <N, {/Symbol y}> / {/Symbol y}(t_*) for N = S''/6 and S''/3"
  set ylabel "pairing / {/Symbol y}(t_*) [1]"
  set autoscale y
  plot 1 with lines dt 2 lw 1.5 lc rgb "black" title "Lemma 5's claimed limit 1", \
       0.5 with lines dt 3 lw 1.5 lc rgb "#808080" title "1/2", \
       for [i=1:5] file(i) skip 1 using 1:2 with linespoints pt 7 ps 0.7 lw 1.5 \
         lc rgb word(colors, i) notitle, \
       for [i=1:5] file(i) skip 1 using 1:3 with linespoints pt 6 ps 0.9 lw 1.5 dt 4 \
         lc rgb word(colors, i) notitle, \
       1/0 with linespoints pt 7 ps 0.7 lw 1.5 lc rgb "black" title "N_{/Symbol e} = S''/6 (Lemma 5)", \
       1/0 with linespoints pt 6 ps 0.9 lw 1.5 dt 4 lc rgb "black" title "S''/3", \
       1/0 with lines lw 0 lc rgb "white" title "(colours: {/Symbol y}, see (b))"

  set title "(b) convergence to 1/2"
  set ylabel "|<N_{/Symbol e}, {/Symbol y}>/{/Symbol y}(t_*) - 1/2| [1]"
  set logscale y
  set autoscale y
  set format y "10^{%T}"
  plot for [i=1:5] file(i) skip 1 using 1:(abs($4)) with points pt 7 ps 0.9 \
         lc rgb word(colors, i) title word(titles, i), \
       for [i=1:5] file(i) skip 1 using 1:(abs($5)) with lines dt 2 lw 1.2 \
         lc rgb word(colors, i) notitle, \
       1/0 with lines dt 2 lw 1.2 lc rgb "black" title "|{/Symbol y}''(t_*)| {/Symbol e}^2 / (24 |{/Symbol y}(t_*)|)"

  set title "(c) share of each cubic piece"
  set ylabel "piece's pairing / {/Symbol y}(t_*) [1]"
  unset logscale y
  set format y "%g"
  set autoscale y
  plot 0.5 with lines dt 2 lw 1.5 lc rgb "black" title "proof's value 1/2 per piece", \
       0.25 with lines dt 3 lw 1.5 lc rgb "#808080" title "1/4", \
       for [i=1:5] file(i) skip 1 using 1:6 with linespoints pt 7 ps 0.7 lw 1.5 \
         lc rgb word(colors, i) notitle, \
       for [i=1:5] file(i) skip 1 using 1:7 with linespoints pt 6 ps 0.9 lw 1.5 dt 4 \
         lc rgb word(colors, i) notitle, \
       1/0 with linespoints pt 7 ps 0.7 lw 1.5 lc rgb "black" title "S_1'' piece, (t_*-{/Symbol e}, t_*]", \
       1/0 with linespoints pt 6 ps 0.9 lw 1.5 dt 4 lc rgb "black" title "S_2'' piece, [t_*, t_*+{/Symbol e})"

  unset multiplot
  set bmargin
  unset offsets
  set output
}
