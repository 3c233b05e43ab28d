# Figure 2 (Section 5.1): S_eps for eps = 1e-3, t* = 5. Left, (a), (c), (e): the cubic pieces S_1,
# S_2 and their derivatives on [t* - eps, t* + eps]; right, (b), (d), (f): S_3, S_1, S_2, S_4 on
# [0, 10]. Panels are lettered along the rows, as they are read; each key sits right of its panel.
# Lines: the paper's formulas with the corrected S_2; circles: GSL's natural cubic spline through
# the same data (3 knots on the left, 5 knots on [0, 10] on the right); dashed grey in (a): S_2 as
# printed. N = S'' (= u'' with f = 0, a force per unit mass; Lemma 5's N_eps is S''/6).
# Usage: gnuplot -e "results='results/figure2'" experiments/figure2/plot.gp
if (!exists("results")) results = 'results/figure2'
pieces = results.'/pieces.csv'
printed = results.'/s2_printed.csv'
set datafile separator ','

t_star = 5.0
eps = 1e-3
piece(n, col) = (column(2) == n ? column(col) : NaN)
cubic(col) = (column(2) == 1 || column(2) == 2 ? column(col) : NaN)

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,1150 font ",10"
    set output 'figures/figure2.png'
  } else {
    set terminal svg size 1300,1150 font ",10" dynamic
    set output 'figures/figure2.svg'
  }
  set multiplot layout 3,2 columnsfirst title \
      "Figure 2: spline approximation S_{/Symbol e} of the impact, {/Symbol e} = 10^{-3}, t_* = 5 (S_2 corrected)"
  set grid

  # Left column: the contact interval.
  set xrange [t_star - eps : t_star + eps]  # fixed range: the contact interval of the pieces
  set xtics 0.0005 format "%.4f"
  set xlabel "t [s]"
  set key outside right top box opaque samplen 2 width -2

  # u in mm, so that the tics read -1.2 rather than -1.2x10^{-3} (and 0 rather than 0.0x10^0).
  # The note sits below the printed S_2, where no curve runs.
  set title "(a) displacement: S_1, S_2"
  printed_jump = -1.5 * eps + 1.5 * eps**2  # S_2(t* + eps) - S_4(t* + eps) with S_2 as printed
  set offsets 0, 0, graph 0.05, graph 0.12
  set label 1 sprintf("S_2 as printed ends at S_2(t_*+{/Symbol e}) - S_4(t_*+{/Symbol e}) = %.5g mm", \
      1e3 * printed_jump) at graph 0.98, graph 0.04 right
  set ylabel "u(t) [mm]"
  set autoscale y
  plot pieces skip 1 using 1:(1e3 * piece(1, 3)) with lines lw 2 lc rgb "#0072B2" title "S_1", \
       '' skip 1 using 1:(1e3 * piece(2, 3)) with lines lw 2 lc rgb "#D55E00" title "S_2 (corrected)", \
       printed skip 1 using 1:(1e3 * $2) with lines lw 1.5 dt 2 lc rgb "#808080" title "S_2 as printed", \
       pieces skip 1 every 20 using 1:(1e3 * cubic(6)) with points pt 6 ps 0.8 lc rgb "black" \
         title "GSL natural spline"

  unset label 1
  set offsets 0, 0, graph 0.05, graph 0.05
  set title "(c) velocity: S_1', S_2'"
  set ylabel "v(t) [m/s]"
  plot pieces skip 1 using 1:(piece(1, 4)) with lines lw 2 lc rgb "#0072B2" title "S_1'", \
       '' skip 1 using 1:(piece(2, 4)) with lines lw 2 lc rgb "#D55E00" title "S_2'", \
       '' skip 1 every 20 using 1:(cubic(7)) with points pt 6 ps 0.8 lc rgb "black" \
         title "GSL natural spline"

  set title "(e) contact force: N = S_1'', S_2''"
  set ylabel "N(t) [m/s^2]"
  plot pieces skip 1 using 1:(piece(1, 5)) with lines lw 2 lc rgb "#0072B2" title "S_1''", \
       '' skip 1 using 1:(piece(2, 5)) with lines lw 2 lc rgb "#D55E00" title "S_2''", \
       '' skip 1 every 20 using 1:(cubic(8)) with points pt 6 ps 0.8 lc rgb "black" \
         title "GSL natural spline"

  # Right column: the whole trajectory.
  set xrange [*:*] noextend
  set xtics 1 format "%g"

  set title "(b) displacement: S_3, S_1, S_2, S_4"
  set ylabel "u(t) [m]"
  plot pieces skip 1 using 1:(piece(3, 3)) with lines lw 2 lc rgb "#009E73" title "S_3", \
       '' skip 1 using 1:(piece(1, 3)) with lines lw 2 lc rgb "#0072B2" title "S_1", \
       '' skip 1 using 1:(piece(2, 3)) with lines lw 2 lc rgb "#D55E00" title "S_2", \
       '' skip 1 using 1:(piece(4, 3)) with lines lw 2 lc rgb "#CC79A7" title "S_4", \
       '' skip 1 every 50 using 1:9 with points pt 6 ps 0.8 lc rgb "black" \
         title "GSL natural spline (5 knots)"

  set title "(d) velocity: S_3', S_1', S_2', S_4'"
  set ylabel "v(t) [m/s]"
  plot pieces skip 1 using 1:(piece(3, 4)) with lines lw 2 lc rgb "#009E73" title "S_3'", \
       '' skip 1 using 1:(piece(1, 4)) with lines lw 2 lc rgb "#0072B2" title "S_1'", \
       '' skip 1 using 1:(piece(2, 4)) with lines lw 2 lc rgb "#D55E00" title "S_2'", \
       '' skip 1 using 1:(piece(4, 4)) with lines lw 2 lc rgb "#CC79A7" title "S_4'", \
       '' skip 1 every 50 using 1:10 with points pt 6 ps 0.8 lc rgb "black" \
         title "GSL natural spline (5 knots)"

  set title "(f) contact force: N = S''"
  set ylabel "N(t) [m/s^2]"
  plot pieces skip 1 using 1:(piece(3, 5)) with lines lw 2 lc rgb "#009E73" title "S_3''", \
       '' skip 1 using 1:(piece(1, 5)) with lines lw 2 lc rgb "#0072B2" title "S_1''", \
       '' skip 1 using 1:(piece(2, 5)) with lines lw 2 lc rgb "#D55E00" title "S_2''", \
       '' skip 1 using 1:(piece(4, 5)) with lines lw 2 lc rgb "#CC79A7" title "S_4''", \
       '' skip 1 every 50 using 1:11 with points pt 6 ps 0.8 lc rgb "black" \
         title "GSL natural spline (5 knots)"

  unset multiplot
  set output
}
