# Section 4: convergence of u_h as h -> 0 (figures/convergence.*) and the subsequences with a fixed
# fraction theta of the step before the impact (figures/convergence_subsequences.*).
# Usage: gnuplot -e "results='results/convergence'" experiments/convergence/plot.gp
if (!exists("results")) results = 'results/convergence'
series(name) = results.'/series_'.name.'.csv'
subsequence(name) = results.'/subsequence_'.name.'.csv'
set datafile separator ','

direct = "#D55E00"
direct_cor = "#0072B2"
aligned = "#009E73"
mj = "#CC79A7"
mj_cor = "#56B4E9"
grey = "#808080"

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,1000 font ",10"
    set output 'figures/convergence.png'
  } else {
    set terminal svg size 1300,1000 font ",10" dynamic
    set output 'figures/convergence.svg'
  }
  set multiplot layout 2,2 title \
      "Section 4: does u_h of (4-1)-(4-3) converge? u^0 = 5 (or 5.0123), v^0 = -1 m/s, T = 10 s"
  set grid
  set logscale x
  set xlabel "time step h [s]"
  set format x "10^{%T}"
  set xrange [*:*] noextend
  set autoscale y
  # Every key below its panel, three rows each (a blank key title keeps it off the x label), so
  # that the panels of a row line up; the log axes a little past the data.
  set offsets graph 0.02, graph 0.02, graph 0.04, graph 0.04
  set bmargin 10
  set key below maxrows 3 nobox font ",9" title " "

  set title "(a) f = 0: sup-norm error max_l |u^l - u(t_l)|"
  set logscale y
  set format y "10^{%T}"
  set ylabel "error [m]"
  plot series('f0_direct') skip 1 using 1:3 with linespoints pt 7 ps 0.8 lc rgb direct \
         title "direct, no COR, t* off grid (u^0 = 5.0123)", \
       series('f0_direct_aligned') skip 1 using 1:3 with linespoints pt 5 ps 0.7 lc rgb aligned \
         title "direct, no COR, t* on grid (u^0 = 5, h = 5/m)", \
       series('f0_direct_cor') skip 1 using 1:3 with linespoints pt 9 ps 0.8 lc rgb direct_cor \
         title "direct, COR = 0.75", \
       series('f0_mj') skip 1 using 1:3 with linespoints pt 6 ps 0.8 lc rgb mj \
         title "moreau\\_jean, e = 1", \
       series('f0_mj_cor') skip 1 using 1:3 with linespoints pt 8 ps 0.8 lc rgb mj_cor \
         title "moreau\\_jean, COR = 0.75", \
       x with lines dt 2 lc rgb grey title "h (first order)"

  set title "(b) f = -9.80665 m/s^2 (u^0 = 5): sup-norm error"
  plot series('g_direct') skip 1 using 1:3 with linespoints pt 7 ps 0.8 lc rgb direct \
         title "direct, no COR", \
       series('g_direct_cor') skip 1 using 1:3 with linespoints pt 9 ps 0.8 lc rgb direct_cor \
         title "direct, COR = 0.75", \
       series('g_mj') skip 1 using 1:3 with linespoints pt 6 ps 0.8 lc rgb mj \
         title "moreau\\_jean, e = 1", \
       series('g_mj_cor') skip 1 using 1:3 with linespoints pt 8 ps 0.8 lc rgb mj_cor \
         title "moreau\\_jean, COR = 0.75", \
       10 * x with lines dt 2 lc rgb grey title "10 h (first order)"

  set title "(c) effective COR of the first impact, -v_a / v_b (no COR given)"
  unset logscale y
  set format y "%g"
  set ylabel "effective COR [1]"
  set yrange [-0.05 : 1.15]  # fixed range: a COR lies in [0, 1], drawn whole
  plot series('f0_direct') skip 1 using 1:4 with points pt 7 ps 1.0 lc rgb direct \
         title "direct, f = 0, u^0 = 5.0123", \
       '' skip 1 using 1:(abs(1 - 2 * $2)) with points pt 6 ps 1.8 lc rgb "black" \
         title "|1 - 2{/Symbol q}|, {/Symbol q} = fraction of the step before t*", \
       series('g_direct') skip 1 using 1:4 with points pt 5 ps 0.8 lc rgb direct_cor \
         title "direct, f = -9.80665", \
       series('f0_direct_aligned') skip 1 using 1:4 with points pt 4 ps 0.8 lc rgb aligned \
         title "direct, f = 0, t* on grid", \
       series('f0_mj') skip 1 using 1:4 with lines lw 2 lc rgb mj title "moreau\\_jean (e = 1)"

  set title "(d) the proof's identities (4-9), (4-10) and the energy lost"
  set logscale y
  set format y "10^{%T}"
  set ylabel "|(4-9)| [m/s], |(4-10)| [m^2/s], energy [m^2/s^2]"
  set autoscale y
  plot series('g_direct') skip 1 using 1:(abs($6)) with linespoints pt 7 ps 0.8 lc rgb direct \
         title "(4-9) as printed, direct, f = -9.8, no COR", \
       '' skip 1 using 1:(abs($7)) with linespoints pt 6 ps 0.8 lc rgb direct \
         title "(4-9) with -f T, direct, f = -9.8, no COR", \
       series('g_direct_cor') skip 1 using 1:(abs($7)) with linespoints pt 9 ps 0.8 \
         lc rgb direct_cor title "(4-9) with -f T, direct, COR = 0.75", \
       series('g_mj') skip 1 using 1:(abs($8)) with linespoints pt 8 ps 0.8 lc rgb mj \
         title "(4-10) h{/Symbol S} N^l (u^{l+1} - {/Symbol f}), moreau\\_jean (direct: 0)", \
       series('f0_direct') skip 1 using 1:10 with linespoints pt 5 ps 0.7 lc rgb aligned \
         title "E^0 - E^n = {/Symbol S} N^l (u^l - {/Symbol f}), direct, f = 0, no COR"

  unset multiplot
  set bmargin
  set output
}

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,520 font ",10"
    set output 'figures/convergence_subsequences.png'
  } else {
    set terminal svg size 1300,520 font ",10" dynamic
    set output 'figures/convergence_subsequences.svg'
  }
  set multiplot layout 1,2 title \
      "Section 4: subsequences h = t*/(m + {/Symbol q}) of direct (no COR, f = 0, u^0 = 5.0123, v^0 = -1 m/s) converge to different solutions"
  set grid
  set logscale x
  set logscale y
  set xlabel "time step h [s]"
  set format x "10^{%T}"
  set format y "10^{%T}"
  set xrange [*:*] noextend
  set autoscale y
  set ylabel "sup-norm error [m]"
  set title "(a) max_l |u^l - u_e(t_l)| against the exact solution u_e with COR e"
  set key below maxrows 3 nobox font ",9" title " "
  plot series('f0_direct_aligned') skip 1 using 1:3 with linespoints pt 5 ps 0.7 lc rgb aligned \
         title "{/Symbol q} = 0 (u^0 = 5), against e = 1", \
       subsequence('theta_0_25') skip 1 using 2:5 with linespoints pt 7 ps 0.8 lc rgb direct_cor \
         title "{/Symbol q} = 1/4, against e = 1/2", \
       subsequence('theta_0_75') skip 1 using 2:5 with linespoints pt 9 ps 0.8 lc rgb mj \
         title "{/Symbol q} = 3/4, against e = 1/2", \
       subsequence('theta_0_5') skip 1 using 2:5 with linespoints pt 13 ps 0.8 lc rgb mj_cor \
         title "{/Symbol q} = 1/2, against e = 0", \
       series('f0_direct') skip 1 using 1:3 with linespoints pt 6 ps 0.8 lc rgb direct \
         title "generic h (log-spaced), against e = 1", \
       x with lines dt 2 lc rgb grey title "h"

  set title "(b) u_h at m = 250 (h {/Symbol \273} 0.02 s) and the limits u_e"
  unset logscale x
  unset logscale y
  set format x "%g"
  set format y "%g"
  set xlabel "t [s]"
  set ylabel "u(t) [m]"
  unset offsets
  set xrange [*:*] noextend
  set autoscale y
  set key below maxrows 3 nobox font ",9" samplen 2 title " "
  path(k) = results.'/path_theta_'.k.'.csv'
  plot path(0) skip 1 every 10 using 1:2 with points pt 5 ps 0.6 lc rgb aligned \
         title "u_h, {/Symbol q} = 0", \
       '' skip 1 using 1:3 with lines lw 1.5 lc rgb aligned title "u_e, e = 1", \
       path(1) skip 1 every 10 using 1:2 with points pt 7 ps 0.6 lc rgb direct_cor \
         title "u_h, {/Symbol q} = 1/4", \
       '' skip 1 using 1:3 with lines lw 1.5 lc rgb direct_cor title "u_e, e = 1/2", \
       path(3) skip 1 every 10 using 1:2 with points pt 9 ps 0.6 lc rgb mj \
         title "u_h, {/Symbol q} = 3/4 (limit e = 1/2)", \
       path(2) skip 1 every 10 using 1:2 with points pt 13 ps 0.6 lc rgb mj_cor \
         title "u_h, {/Symbol q} = 1/2", \
       '' skip 1 using 1:3 with lines lw 1.5 lc rgb mj_cor title "u_e, e = 0"

  unset multiplot
  set output
}
