# The ball on a vibrating table y = a sin(omega t) (omega = 2 pi 10 rad/s, g = 9.80665 m/s^2),
# Gamma = a omega^2 / g, restitution e on the relative velocity. Four figures:
#  vibrating_table: bifurcation diagrams of the exact solution, impact phase omega t mod 2 pi against
#    Gamma after a transient, for a sweep up (from rest on the table) and a sweep down (each run
#    continues from the previous one), with the lift-offs after a rest (sticking), the closed-form
#    period-1 phase and thresholds (paper_notes/vibrating_table.md);
#  vibrating_table_steppers: the same diagrams from direct and moreau_jean at two steps over the
#    exact one;
#  vibrating_table_thresholds: the thresholds each method shows against h;
#  vibrating_table_trajectories: one trajectory per regime in the table's frame.
# Usage: gnuplot -e "results='results/vibrating_table'" experiments/vibrating_table/plot.gp
if (!exists("results")) results = 'results/vibrating_table'
set datafile separator ','
diagram = results.'/diagram_exact.csv'
steppers = results.'/diagram_steppers.csv'
thresholds = results.'/thresholds.csv'
trajectories = results.'/trajectories.csv'
regimes = results.'/regimes.csv'

blue = "#0072B2"; orange = "#E69F00"; green = "#009E73"; red = "#D55E00"; pink = "#CC79A7"
gray = "#999999"

# The closed forms: Gamma_1 = pi n (1 - e)/(1 + e), Gamma_pd = sqrt(Gamma_1^2 + (2 (1 + e^2)/(1 + e)^2)^2),
# the stable period-1 phase acos(Gamma_1 / Gamma), the saddle's -acos(...) + 2 pi.
g1(e, n) = pi * n * (1 - e) / (1 + e)
gpd(e, n) = sqrt(g1(e, n)**2 + (2 * (1 + e**2) / (1 + e)**2)**2)
stable(e, x) = (x >= g1(e, 1) && x <= gpd(e, 1)) ? acos(g1(e, 1) / x) : NaN
unstable(e, x) = (x >= gpd(e, 1)) ? acos(g1(e, 1) / x) : NaN
saddle(e, x) = (x >= g1(e, 1)) ? 2 * pi - acos(g1(e, 1) / x) : NaN
is(col, text) = strcol(col) eq text
pick(method, e, sweep, kind) = (is(1, method) && abs($3 - e) < 1e-9 && is(4, sweep) && is(6, kind)) ? $5 : NaN
pick_h(method, h, e, kind) = (is(1, method) && abs($2 / h - 1) < 1e-9 && abs($3 - e) < 1e-9 && is(6, kind)) ? $5 : NaN

# Every threshold as a vertical line (arrows, which a key does not list: the plots add NaN entries).
thresholds_marks(e) = sprintf("set arrow 1 from %g, graph 0 to %g, graph 1 nohead lw 1.5 dt 2 lc rgb 'black'; set arrow 2 from %g, graph 0 to %g, graph 1 nohead lw 1.5 dt 3 lc rgb 'black'; set arrow 3 from %g, graph 0 to %g, graph 1 nohead lw 1 dt 2 lc rgb '%s'; set arrow 4 from %g, graph 0 to %g, graph 1 nohead lw 1 dt 3 lc rgb '%s'; set arrow 5 from 1, graph 0 to 1, graph 1 nohead lw 1 lc rgb '%s'", g1(e, 1), g1(e, 1), gpd(e, 1), gpd(e, 1), g1(e, 2), g1(e, 2), pink, gpd(e, 2), gpd(e, 2), pink, gray)

set style textbox opaque noborder
do for [format in "png pdf"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,1000 font ",10"
    set output 'figures/vibrating_table.png'
  } else {
    set terminal pdfcairo size 8.7in,6.7in font ",7"
    set output 'figures/vibrating_table.pdf'
  }
  set multiplot layout 2,1 title "Ball on a vibrating table (exact solution): impact phase after a transient of 40 table periods, 20 periods kept per {/Symbol G}"
  set grid
  set xrange [0.2:2.6]  # fixed range: the sweeps' range of Gamma (no impact below Gamma_1 is part of it)
  set yrange [0:2 * pi]  # fixed range: a phase mod 2 pi, drawn whole
  set ytics ("0" 0, "{/Symbol p}/2" pi / 2, "{/Symbol p}" pi, "3{/Symbol p}/2" 3 * pi / 2, "2{/Symbol p}" 2 * pi)
  set xlabel "{/Symbol G} = a {/Symbol w}^2 / g [1]"
  set ylabel "impact phase {/Symbol w}t mod 2{/Symbol p} [rad]"
  # One key for both panels, below the second: both draw the same series.
  set samples 1000
  do for [e in "0.5 0.8"] {
    ee = e + 0
    if (e eq "0.5") { set key off; set bmargin } else { set key below maxrows 4 nobox title " "; set bmargin 9 }
    eval thresholds_marks(ee)
    # Runs of exact that stopped with a numerical failure (regimes.csv), marked at the bottom.
    stats regimes skip 1 using (is(1, "exact") && abs($3 - ee) < 1e-9 && is(6, "failed") ? 1 : 0) nooutput
    failed = STATS_sum
    set title sprintf("e = %s: {/Symbol G}_1 = %.4f, {/Symbol G}_{pd} = %.4f (n = 1)", e, g1(ee, 1), gpd(ee, 1))
    plot diagram skip 1 using (pick("exact", ee, "up", "impact")):7 with points pt 7 ps 0.12 lc rgb orange title "impacts, sweep up from rest", \
         diagram skip 1 using (pick("exact", ee, "down", "impact")):7 with points pt 7 ps 0.12 lc rgb blue title "impacts, sweep down", \
         diagram skip 1 using (pick("exact", ee, "up", "lift")):7 with points pt 1 ps 0.5 lc rgb red title "lift-off after a rest (sticking), up", \
         diagram skip 1 using (pick("exact", ee, "down", "lift")):7 with points pt 2 ps 0.5 lc rgb green title "lift-off after a rest, down", \
         stable(ee, x) + 0.12 with lines lw 1 lc rgb "black" title "period 1, stable (closed form), drawn 0.12 rad above", \
         unstable(ee, x) with lines lw 1 dt 2 lc rgb "black" title "period 1 past {/Symbol G}_{pd} (unstable)", \
         saddle(ee, x) with lines lw 1 dt 4 lc rgb gray title "period 1, saddle branch", \
         regimes skip 1 using (is(1, "exact") && abs($3 - ee) < 1e-9 && is(6, "failed") ? $5 : NaN):(0.08) with points pt 2 ps 0.8 lc rgb "black" title (failed > 0 ? "run stopped: exact failed numerically" : ""), \
         NaN with lines lw 1.5 dt 2 lc rgb "black" title "{/Symbol G}_1, n = 1: period 1 appears", \
         NaN with lines lw 1.5 dt 3 lc rgb "black" title "{/Symbol G}_{pd}, n = 1: period doubling", \
         NaN with lines lw 1 dt 2 lc rgb pink title "n = 2: {/Symbol G}_1 dashed, {/Symbol G}_{pd} dotted", \
         NaN with lines lw 1 lc rgb gray title "{/Symbol G} = 1: a resting ball lifts off above it"
  }
  unset multiplot
  unset arrow
  set bmargin

  if (format eq "png") {
    set terminal pngcairo size 1300,1050 font ",10"
    set output 'figures/vibrating_table_steppers.png'
  } else {
    set terminal pdfcairo size 8.7in,7in font ",7"
    set output 'figures/vibrating_table_steppers.pdf'
  }
  # The thresholds are named in the title: four more key entries would cover the branches.
  set multiplot layout 2,2 title "Time-steppers on the vibrating table: impact phases of both sweeps (impacts as impact run --events dates them: where the step's flight crosses the table) over the exact ones\nvertical lines: {/Symbol G}_1 dashed and {/Symbol G}_{pd} dotted (black n = 1, pink n = 2), {/Symbol G} = 1 gray, as in the exact solution's diagram"
  # One key for the four panels, along the bottom of the figure, in a margin every panel keeps.
  set bmargin 5
  do for [e in "0.5 0.8"] {
    ee = e + 0
    do for [method in "direct moreau_jean"] {
      eval thresholds_marks(ee)
      set title sprintf("%s, e = %s", method, e) noenhanced
      if (e eq "0.5" && method eq "direct") { set key at screen 0.5, screen 0.005 center bottom horizontal nobox } else { set key off }
      plot diagram skip 1 using (pick("exact", ee, "up", "impact")):7 with points pt 7 ps 0.3 lc rgb gray title "exact", \
           diagram skip 1 using (pick("exact", ee, "down", "impact")):7 with points pt 7 ps 0.3 lc rgb gray notitle, \
           steppers skip 1 using (pick_h(method, 1e-3, ee, "impact")):7 with points pt 7 ps 0.15 lc rgb orange title "h = 10^{-3} s", \
           steppers skip 1 using (pick_h(method, 1e-4, ee, "impact")):7 with points pt 7 ps 0.15 lc rgb blue title "h = 10^{-4} s", \
           stable(ee, x) with lines lw 1.5 lc rgb "black" title "period 1 (closed form)"
    }
  }
  unset multiplot
  unset arrow
  set bmargin
}

# Thresholds against h: measured - closed form. Rows of thresholds.csv: method,h,e,existence,
# period_doubling,fit_points; the closed_form rows have h = 0.
shift(method, e, col, ref) = (is(1, method) && abs($3 - e) < 1e-9) ? column(col) - ref : NaN
do for [format in "png pdf"] {
  if (format eq "png") {
    set terminal pngcairo size 1200,900 font ",10"
    set output 'figures/vibrating_table_thresholds.png'
  } else {
    set terminal pdfcairo size 8in,6in font ",7"
    set output 'figures/vibrating_table_thresholds.pdf'
  }
  set multiplot layout 2,2 title "Thresholds of the period-1 orbit as each method shows them (continuation sweeps in steps of 0.005, ends of the period-1 branch bisected)"
  set grid
  set autoscale y
  set xrange [*:*] noextend
  set logscale x
  set format x "10^{%L}"
  set xlabel "h [s]"
  set bmargin 7
  set key below maxrows 3 nobox noenhanced title " "
  set offsets graph 0.05, graph 0.05, graph 0.05, graph 0.05
  set ytics auto
  do for [e in "0.5 0.8"] {
    ee = e + 0
    set ylabel "{/Symbol G}(split = 0.1) - exact's [1]"
    set title sprintf("period-2 branch: {/Symbol G} where its split reaches 0.1 g/{/Symbol w}, e = %s", e) enhanced
    plot thresholds skip 1 using 2:(is(1, "direct") && abs($3 - ee) < 1e-9 ? $8 : NaN) with linespoints pt 7 lc rgb blue title "direct", \
         thresholds skip 1 using 2:(is(1, "moreau_jean") && abs($3 - ee) < 1e-9 ? $8 : NaN) with linespoints pt 5 lc rgb orange title "moreau_jean", \
         0 with lines lc rgb gray notitle
    set ylabel "{/Symbol G}_1(h) - {/Symbol G}_1 [1]"
    set title sprintf("end of the period-1 branch, e = %s: {/Symbol G}_1 = %.6f", e, g1(ee, 1)) enhanced
    plot thresholds skip 1 using 2:(shift("direct", ee, 4, g1(ee, 1))) with linespoints pt 7 lc rgb blue title "direct", \
         thresholds skip 1 using 2:(shift("moreau_jean", ee, 4, g1(ee, 1))) with linespoints pt 5 lc rgb orange title "moreau_jean", \
         thresholds skip 1 using (1e-4):(shift("exact", ee, 4, g1(ee, 1))) with points pt 9 ps 2 lc rgb "black" title "exact (h-independent)", \
         0 with lines lc rgb gray notitle
  }
  unset multiplot
  unset offsets
  set bmargin
  unset logscale x
  set format x "% h"
}

# Trajectories: u(t) (mm) relative to the table over four periods, from the exact solution.
regime(name) = is(1, name) ? $5 * 1000 : NaN
do for [format in "png pdf"] {
  if (format eq "png") {
    set terminal pngcairo size 1200,900 font ",10"
    set output 'figures/vibrating_table_trajectories.png'
  } else {
    set terminal pdfcairo size 8in,6in font ",7"
    set output 'figures/vibrating_table_trajectories.pdf'
  }
  set multiplot layout 2,2 title "One trajectory per regime (exact solution, e = 0.5, on the attractor of the downward sweep): height above the table"
  set grid
  unset xrange
  set autoscale x
  set xlabel "t [s] (from a state on the attractor)"
  set ylabel "u = x - y [mm]"
  set yrange [0:*]  # fixed range: a height above the table, drawn from 0
  unset key
  names = "period_one period_two chaos sticking"
  gammas = "1.3 1.6 1.75 1.03"
  labels = "'period 1' 'period 2' 'chaos' 'sticking and chattering'"
  do for [k = 1:4] {
    set title sprintf("%s: {/Symbol G} = %s", word(labels, k), word(gammas, k)) enhanced
    plot trajectories skip 1 using 4:(regime(word(names, k))) with lines lw 1.5 lc rgb blue notitle
  }
  unset multiplot
}
