# Lemma 1 (Section 3): E(t) and the relative deviation |s (L E)(s) - E(0)| / |E(0)| from the
# lemma's (L E)(s) = E(0)/s. Left: the exact solution; right: the direct scheme (h = 0.001 unless
# noted). Top: what is transformed; bottom: the deviation, lines = GSL quadrature, points = the
# closed form sum_k dE_k exp(-s t_k) from the jumps of E. A deviation of exactly 0 is drawn at the
# bottom of the axis (1e-18).
# Usage: gnuplot -e "results='results/lemma1'" experiments/lemma1/plot.gp
if (!exists("results")) results = 'results/lemma1'
set datafile separator ','

at_least(x) = abs(x) < 1e-18 ? 1e-18 : abs(x)
exact_cases = "exact_f0_elastic exact_f0_cor075 exact_gravity_elastic exact_gravity_cor075 exact_gravity_plastic"
exact_titles = "'f = 0, elastic' 'f = 0, COR 0.75' 'f = -9.80665, elastic' 'f = -9.80665, COR 0.75' 'f = -9.80665, plastic (COR 0)'"
scheme_cases = "direct_f0_no_cor direct_f0_no_cor_h0012 direct_f0_cor075 direct_gravity_no_cor direct_gravity_cor075"
scheme_titles = "'f = 0, no COR' 'f = 0, no COR, h = 0.0012' 'f = 0, COR 0.75' 'f = -9.80665, no COR' 'f = -9.80665, COR 0.75'"
# One colour per scene, the same in both columns (the exact solution's "elastic" is the scheme's
# "no COR"); the plastic scene has no scheme run, the h = 0.0012 run no exact one.
exact_colors = "#1b9e77 #d95f02 #7570b3 #e7298a #66a61e"
scheme_colors = "#1b9e77 #e6ab02 #d95f02 #7570b3 #e7298a"
# Dashed: the gravity scene without COR, which lies on the f = 0 one in (a).
exact_dashes(i) = i == 3 ? 2 : 1
scheme_dashes(i) = i == 4 ? 2 : 1

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1400,900 font ",10"
    set output 'figures/lemma1.png'
  } else {
    set terminal svg size 1400,900 font ",10" dynamic
    set output 'figures/lemma1.svg'
  }
  set multiplot layout 2,2 title "Lemma 1: s (L E)(s) = E(0) for s > 1? (u_0 = 5 m, v_0 = -1 m/s, {/Symbol f} = 0)\nin (c) and (d) a deviation of exactly 0 is drawn on the bottom axis, at 10^{-18}"

  set xlabel "t [s]"
  set ylabel "E(t) / E(0) [1]"
  set xrange [*:*] noextend
  set yrange [0:*]  # fixed range: a share of E(0), drawn from 0
  set offsets 0, 0, graph 0.05, graph 0.05
  # Each key right of its panel, in a margin of the same width everywhere, so the panels line up.
  set rmargin 33
  set key outside right top nobox font ",9"
  set grid
  set title "(a) exact solution: energy E = v^2/2 - f u"
  plot for [i=1:5] sprintf("%s/energy_%s.csv", results, word(exact_cases, i)) \
       using 1:2 with lines lw 2 dt exact_dashes(i) lc rgb word(exact_colors, i) \
       title word(exact_titles, i)
  set title "(b) direct scheme (5-1): energy E^l = (v^l)^2/2 - f u^l"
  plot for [i=1:5] sprintf("%s/energy_%s.csv", results, word(scheme_cases, i)) \
       using 1:2 with lines lw 2 dt scheme_dashes(i) lc rgb word(scheme_colors, i) \
       title word(scheme_titles, i)

  set xlabel "s [1/s]"
  set ylabel "|s (L E)(s) - E(0)| / |E(0)| [1]"
  unset offsets
  set yrange [1e-18:*]  # fixed range: a deviation of exactly 0 is drawn at 1e-18, the axis bottom
  set logscale y 10
  set format y "10^{%L}"
  set title "(c) exact solution on [0, inf): lines GSL quadrature, circles sum_k dE_k e^{-s t_k}"
  plot for [i=1:5] sprintf("%s/deviation.csv", results) \
         using 1:(at_least(column(word(exact_cases, i)))) with lines lw 2 dt exact_dashes(i) \
         lc rgb word(exact_colors, i) title word(exact_titles, i), \
       for [i=1:5] sprintf("%s/deviation.csv", results) \
         using 1:(at_least(column(word(exact_cases, i)."_predicted"))) with points pt 6 ps 1 \
         lc rgb word(exact_colors, i) notitle, \
       1e-16 with lines lc rgb "black" lw 1.5 dt 2 title "round-off of E (1e-16)"
  set title "(d) direct scheme to T = 40 s, E^l interpolated linearly; circles as in (c)"
  plot for [i=1:5] sprintf("%s/deviation.csv", results) \
         using 1:(at_least(column(word(scheme_cases, i)))) with lines lw 2 dt scheme_dashes(i) \
         lc rgb word(scheme_colors, i) title word(scheme_titles, i), \
       for [i=1:5] sprintf("%s/deviation.csv", results) \
         using 1:(at_least(column(word(scheme_cases, i)."_predicted"))) with points pt 6 ps 1 \
         lc rgb word(scheme_colors, i) notitle, \
       1e-16 with lines lc rgb "black" lw 1.5 dt 2 title "round-off of E (1e-16)"
  unset multiplot
  set rmargin
  unset logscale y
  set format y "% h"
}
