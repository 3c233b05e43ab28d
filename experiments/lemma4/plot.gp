# Lemma 4 (uniqueness): (a) solution paths under COR = 1 approach one trajectory as h -> 0,
# (b) exact solutions with perturbed data approach it as delta -> 0, (c)-(d) without COR = 1 two
# weak solutions from the same data and the proof's (4-12)-(4-13) on pairs of solutions,
# (e)-(f) the lemma's condition "u_t^0 = 0 and u_t(t) = w_t(t) = 0 for some t" on two solutions.
# Usage: gnuplot -e "results='results/lemma4'" experiments/lemma4/plot.gp
if (!exists("results")) results = 'results/lemma4'
set datafile separator ','

c1 = "#0072B2"
c2 = "#D55E00"
c3 = "#009E73"
c4 = "#CC79A7"
grey = "#808080"
g = 9.80665
t1 = sqrt(2 * 5.0 / g)

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,1550 font ",10"
    set output 'figures/lemma4.png'
  } else {
    set terminal svg size 1300,1550 font ",10" dynamic
    set output 'figures/lemma4.svg'
  }
  set multiplot layout 3,2 title "Lemma 4 (uniqueness): u^0 = 5 m, v^0 = -1 m/s unless stated"
  set grid
  # Every key below its panel, in a bottom margin of the same height, so that the panels line up.
  set bmargin 12
  set offsets graph 0.03, graph 0.03, 0, 0
  set key below maxrows 4 nobox font ",9" title " "

  set title "(a) COR = 1: distances between solution paths on the grid"
  set logscale xy
  set format x "10^{%T}"
  set format y "10^{%T}"
  set xlabel "time step h [s]"
  set ylabel "max_l |u_a(t_l) - u_b(t_l)| [m]"
  set xrange [*:*] noextend
  set autoscale y
  paths(name) = results.'/paths_'.name.'.csv'
  plot paths('f0') skip 1 using 1:3 with linespoints pt 5 ps 0.7 lc rgb c3 \
         title "direct - exact, f = 0, t* = 5 on the grid", \
       '' skip 1 using 1:2 with linespoints pt 4 ps 0.7 lc rgb grey \
         title "direct - moreau\\_jean, f = 0, t* on grid", \
       paths('f0_cor_1') skip 1 using 1:3 with linespoints pt 7 ps 0.7 lc rgb c1 \
         title "direct (COR = 1) - exact, f = 0, u^0 = 5.0123", \
       '' skip 1 using 1:4 with linespoints pt 6 ps 0.7 lc rgb c1 \
         title "moreau\\_jean - exact, f = 0, u^0 = 5.0123", \
       paths('gravity') skip 1 using 1:3 with linespoints pt 9 ps 0.8 lc rgb c2 \
         title "direct (COR = 1) - exact, f = -9.8", \
       '' skip 1 using 1:4 with linespoints pt 8 ps 0.8 lc rgb c2 \
         title "moreau\\_jean - exact, f = -9.8", \
       '' skip 1 using 1:2 with linespoints pt 12 ps 0.8 lc rgb c4 \
         title "direct (COR = 1) - moreau\\_jean, f = -9.8", \
       x with lines dt 2 lc rgb "black" title "h"

  set title "(b) COR = 1: exact solutions with perturbed initial data"
  set xlabel "perturbation {/Symbol d} of u^0 [m] or of v^0 [m/s]"
  set ylabel "sup_{[0, 10]} |u_{/Symbol d} - u| [m]"
  pert = results.'/perturbation.csv'
  plot pert skip 1 using 1:2 with linespoints pt 7 lc rgb c1 title "f = 0, u^0 + {/Symbol d}", \
       '' skip 1 using 1:3 with linespoints pt 6 lc rgb c1 title "f = 0, v^0 + {/Symbol d}", \
       '' skip 1 using 1:4 with linespoints pt 9 lc rgb c2 title "f = -9.8, u^0 + {/Symbol d}", \
       '' skip 1 using 1:5 with linespoints pt 8 lc rgb c2 title "f = -9.8, v^0 + {/Symbol d}", \
       x with lines dt 2 lc rgb "black" title "{/Symbol d}"

  unset logscale xy
  set format x "%g"
  set format y "%g"
  set xlabel "t [s]"
  set xrange [*:*] noextend
  set offsets 0, 0, graph 0.05, graph 0.05

  set title "(c) two weak solutions of (2-1)-(2-4) from the same data, f = 0"
  set ylabel "u(t) [m]"
  cor = results.'/pair_cor.csv'
  plot cor skip 1 using 1:2 with lines lw 2 lc rgb c1 title "u: COR = 1", \
       '' skip 1 using 1:3 with lines lw 2 dt 2 lc rgb c2 title "w: COR = 1/2"

  set title "(d) (4-12): (z_t^2(t) - z_t^2(0))/2 against -u_t(t) w_t(t) + u_t(0) w_t(0), f = 0"
  set ylabel "value [m^2/s^2]"
  elastic = results.'/pair_elastic.csv'
  plot cor skip 1 using 1:6 with lines lw 2 lc rgb c1 title "COR 1 vs 1/2: left side", \
       '' skip 1 using 1:7 with lines lw 2 dt 2 lc rgb c1 title "COR 1 vs 1/2: -u_t w_t + u_t(0) w_t(0)", \
       elastic skip 1 using 1:6 with lines lw 2 lc rgb c2 \
         title "both elastic, u^0 = 5 vs 5.5: left side", \
       '' skip 1 using 1:7 with lines lw 2 dt 2 lc rgb c3 \
         title "both elastic: -u_t w_t + u_t(0) w_t(0)", \
       '' skip 1 using 1:11 with lines lw 1.5 dt 3 lc rgb "black" \
         title "both elastic: z_t^2(t) - z_t^2(0), which (4-13) says is 0"

  set title "(e) u_t^0 = 0 and u_t = w_t = 0 at t = 2 t_1, f = -9.80665 m/s^2, v^0 = 0"
  set ylabel "u(t) [m]"
  set arrow 1 from 2 * t1, graph 0 to 2 * t1, graph 1 nohead dt 2 lw 1.5 lc rgb "black"
  cond = results.'/pair_condition1.csv'
  plot cond skip 1 using 1:2 with lines lw 2 lc rgb c1 title "u: COR = 1", \
       '' skip 1 using 1:3 with lines lw 2 dt 2 lc rgb c2 title "w: COR = {/Symbol \326}2 - 1", \
       NaN with lines dt 2 lw 1.5 lc rgb "black" title "t = 2 t_1: u_t = w_t = 0"

  set title "(f) the velocities of (e)"
  set ylabel "velocity [m/s]"
  plot cond skip 1 using 1:4 with lines lw 2 lc rgb c1 title "u_t: COR = 1", \
       '' skip 1 using 1:5 with lines lw 2 dt 2 lc rgb c2 title "w_t: COR = {/Symbol \326}2 - 1", \
       0 with lines lc rgb "black" notitle
  unset arrow 1

  unset multiplot
  unset offsets
  set bmargin
  set output
}
