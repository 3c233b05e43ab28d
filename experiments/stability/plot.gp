# Stability maps and the stiff study (experiments/stability, written by exp_stability).
#   figures/stability_map.*     method x case x h: the outcome of each run (colour key below)
#   figures/stability_params.*  fb_newton: epsilon x h; penalty: stepper x c_N and c_N x h
#   figures/stability_stiff.*   penalty as c_N grows: penetration, contact duration, impulse,
#                               error against exact, energy drift, ODE steps
#   <timing>/stability_stiff_time.*  penalty as c_N grows: wall time of each GSL stepper. It
#                               differs from run to run, so it goes to `timing` (results/figures;
#                               `make refresh-timing-figures` copies it to figures/)
# Units: SI as in the paper (f = -9.80665 m/s^2); N and c_N are per unit mass, so c_N is in s^-2.
# Usage: gnuplot -e "results='results/stability'; timing='results/figures'" \
#          experiments/stability/plot.gp
if (!exists("results")) results = 'results/stability'
if (!exists("timing")) timing = 'results/figures'
load results.'/labels.gp'
processor = system("cat '".results."/processor.txt'")

# Outcome colours (the Outcome codes of src/impact/stability.hpp).
array outcome_colour[7] = [0x1a9641, 0xfdd835, 0xd7191c, 0x2b83ba, 0x000000, 0x9e7cc1, 0xd9d9d9]
array outcome_title[7] = ["ok", "inaccurate (error > 1% of the amplitude)", \
    "energy grows where the theory forbids it", "failure reported (did not converge)", \
    "non-finite value caught", "over the work budget (too slow)", "rejected (no COR law)"]
colour(code) = outcome_colour[int(code) + 1]


# The outcome key, drawn by the last panel of a map figure wherever `set key at screen` puts it.
outcome_key = "for [c = 1:7] NaN with boxes lc rgb outcome_colour[c] title outcome_title[c]"
# log10 h on the maps' x axes, labelled every third decade.
h_tics = "set xtics ('10^{-9}' -9, '10^{-6}' -6, '10^{-3}' -3, '1' 0); set mxtics 3"
# The panel in row `row`, column `col` of the 2 x 3 parameter maps. (Macros are expanded when a
# loop is read, so they are all defined here, before it.)
panel_at = "set lmargin at screen 0.075 + (col - 1) * 0.32; set rmargin at screen 0.32 * col + 0.01; set tmargin at screen 0.9 - (row - 1) * 0.43; set bmargin at screen 0.56 - (row - 1) * 0.43"

do for [format in "png svg"] {
  # ---- Figure 1: the extreme cases ----
  reset
  set style fill solid 1.0 noborder
  if (format eq "png") {
    set terminal pngcairo size 2000,760 font ",10"
    set output 'figures/stability_map.png'
  } else {
    set terminal svg size 2000,760 font ",10" dynamic
    set output 'figures/stability_map.svg'
  }
  # The cases label the rows of the first panel only; the others share its rows.
  set multiplot layout 1,5 margins 0.175, 0.985, 0.2, 0.86 spacing 0.012 title \
      "Stability map: outcome of each run, method x case x h (T = min(T_{case}, 10^5 h); penalty: c_N = 10^6 s^{-2}, rk8pd, min(T_{case}, 2 10^4 h))\nu_0 and floor {/Symbol f} in m ({/Symbol f} = 0 unless given), v_0 in m/s, force f in m/s^2, gravity g = -9.80665 m/s^2"
  set xrange [-9.5:0.5]  # fixed range: the grid of the runs, log10 h = -9 .. 0, a cell each
  set yrange [18.5:-0.5]  # fixed range: the 19 cases, a row each
  @h_tics
  set xlabel "h [s]"
  # no ylabel: the rows are the cases, named on the first panel
  unset ylabel
  unset key
  methods = "direct fb_newton moreau_jean exact penalty"
  do for [m = 1:5] {
    set title word(methods, m) noenhanced
    if (m == 1) {
      @set_case_tics
    } else {
      set ytics 0, 1, 18 format ""
    }
    plot results.'/map_cases.dat' index (m - 1) using 3:2:(0.5):(0.5):(colour($4)) \
        with boxxyerror lc rgb variable notitle
  }
  # The outcome key, in a strip of its own along the bottom.
  set lmargin at screen 0.175
  set rmargin at screen 0.985
  set tmargin at screen 0.1
  set bmargin at screen 0.005
  unset title
  unset border
  unset tics
  unset xlabel
  unset ylabel
  set key center center box horizontal maxcols 4 Left reverse noenhanced width 1 \
      title "outcome of the run"
  plot @outcome_key
  unset multiplot

  # ---- Figure 2: epsilon of fb_newton, stepper and c_N of penalty ----
  reset
  set style fill solid 1.0 noborder
  if (format eq "png") {
    set terminal pngcairo size 1800,950 font ",10"
    set output 'figures/stability_params.png'
  } else {
    set terminal svg size 1800,950 font ",10" dynamic
    set output 'figures/stability_params.svg'
  }
  # Top row: the smoothing of fb_newton, then the steppers of penalty on a bounce; bottom row:
  # the steppers and c_N of penalty at rest; below them a strip with the outcome key.
  # (No apostrophes in this loop: gnuplot would take one for a quote and stop expanding macros.)
  set multiplot title \
      "Stability map: the smoothing parameter {/Symbol e} of fb\\_newton and the normal compliance c_N of penalty"
  unset key
  row = 1; col = 1; @panel_at
  set xrange [-9.5:0.5]  # fixed range: the grid of the runs, log10 h = -9 .. 0, a cell each
  @h_tics
  set xlabel "h [s]"
  set ylabel "{/Symbol e} [1]"
  set yrange [-15.5:-1.5]  # fixed range: the grid of the runs, log10 epsilon = -15 .. -2
  set ytics ('10^{-15}' -15, '10^{-12}' -12, '10^{-9}' -9, '10^{-6}' -6, '10^{-3}' -3)
  set mytics 3
  set title "(a) fb\\_newton: bounce from u_0 = 1 m, COR = 1"
  plot results.'/map_eps.dat' index 0 using 3:2:(0.5):(0.5):(colour($4)) \
      with boxxyerror lc rgb variable notitle
  row = 1; col = 2; @panel_at
  set title "(b) fb\\_newton: resting contact, u_0 = {/Symbol f}, v_0 = 0"
  plot results.'/map_eps.dat' index 1 using 3:2:(0.5):(0.5):(colour($4)) \
      with boxxyerror lc rgb variable notitle

  set xrange [1.5:12.5]  # fixed range: the grid of the runs, log10 c_N = 2 .. 12
  set xtics ('10^2' 2, '10^4' 4, '10^6' 6, '10^8' 8, '10^{10}' 10, '10^{12}' 12)
  set mxtics 2
  set xlabel "c_N [s^{-2}]"
  # no ylabel: the rows are the GSL steppers, named on the axis
  unset ylabel
  set yrange [-0.5:6.5]  # fixed range: the seven GSL steppers, a row each
  @set_stepper_tics
  set ytics noenhanced
  set mytics 1
  row = 1; col = 3; @panel_at
  set title "(c) penalty, per GSL stepper: bounce from u_0 = 1 m, h = 10^{-3} s"
  plot results.'/map_stiff.dat' index 0 using 3:2:(0.5):(0.5):(colour($4)) \
      with boxxyerror lc rgb variable notitle
  row = 2; col = 1; @panel_at
  set title "(d) penalty, per GSL stepper: resting contact, h = 10^{-3} s"
  plot results.'/map_stiff.dat' index 1 using 3:2:(0.5):(0.5):(colour($4)) \
      with boxxyerror lc rgb variable notitle

  set xrange [-6.5:-0.5]  # fixed range: the grid of the runs, log10 h = -6 .. -1
  set xtics ('10^{-6}' -6, '10^{-5}' -5, '10^{-4}' -4, '10^{-3}' -3, '10^{-2}' -2, '10^{-1}' -1)
  set mxtics 1
  set xlabel "h [s]"
  set yrange [1.5:12.5]  # fixed range: the grid of the runs, log10 c_N = 2 .. 12
  set ytics ('10^2' 2, '10^4' 4, '10^6' 6, '10^8' 8, '10^{10}' 10, '10^{12}' 12) enhanced
  set mytics 2
  set ylabel "c_N [s^{-2}]"
  do for [i = 1:2] {
    row = 2; col = 1 + i; @panel_at
    set title sprintf("(%s) penalty %s: resting contact", word("e f", i), word("rk8pd msbdf", i))
    plot results.'/map_penalty.dat' index (i - 1) using 3:2:(0.5):(0.5):(colour($4)) \
        with boxxyerror lc rgb variable notitle
  }

  # The outcome key, in a strip of its own along the bottom.
  set lmargin at screen 0.02
  set rmargin at screen 0.98
  set tmargin at screen 0.065
  set bmargin at screen 0.005
  unset title
  unset border
  unset tics
  unset xlabel
  unset ylabel
  set key center center box horizontal maxcols 4 Left reverse noenhanced width 1
  plot @outcome_key
  unset multiplot

  # ---- Figure 3: penalty as c_N grows ----
  reset
  if (format eq "png") {
    set terminal pngcairo size 2000,950 font ",10"
    set output 'figures/stability_stiff.png'
  } else {
    set terminal svg size 2000,950 font ",10" dynamic
    set output 'figures/stability_stiff.svg'
  }
  set datafile separator ','
  stiff = results.'/stiff.csv'
  steppers = "rk8pd rkf45 rkck msadams msbdf rk4imp bsimp"
  array stepper_colour[7] = [0x0072b2, 0x56b4e9, 0x009e73, 0x999999, 0xd55e00, 0xe69f00, 0xcc79a7]
  finished(code) = code <= 1
  pick(st, scene, value) = (strcol(1) eq st && strcol(4) eq scene) ? value : NaN
  set multiplot layout 2,4 title \
      "Normal compliance N = c_N max({/Symbol f} - u, 0) as c_N grows: the Signorini limit (as in Lemma 5) and the cost per GSL stepper"
  set xrange [*:*] noextend
  set offsets graph 0.03, graph 0.03, graph 0.05, graph 0.05
  set logscale xy
  set format x "10^{%L}"
  set format y "10^{%L}"
  set xlabel "c_N [s^{-2}]"
  set grid
  # The colours of the steppers are in the key of the last panel; the key of each panel has only its
  # reference lines, below the panel, in a bottom margin every panel keeps.
  set bmargin 6
  set key below nobox title " "
  V = sqrt(2 * 9.80665)

  set title "(a) first contact at V = 4.43 m/s: penetration (all steppers agree)"
  set ylabel "max({/Symbol f} - u) [m]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", $6)) \
           with points pt 7 ps 0.8 lc rgb stepper_colour[i] notitle, \
       stiff using 3:(pick("rk8pd", "bounce", $7)) with lines lc rgb "black" \
           title "closed form", V / sqrt(x) with lines dt 2 lc rgb "gray40" title "V / c_N^{1/2}"

  set title "(b) first contact: duration"
  set ylabel "contact duration [s]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", $8)) \
           with points pt 7 ps 0.8 lc rgb stepper_colour[i] notitle, \
       stiff using 3:(pick("rk8pd", "bounce", $9)) with lines lc rgb "black" \
           title "closed form", pi / sqrt(x) with lines dt 2 lc rgb "gray40" title "{/Symbol p} / c_N^{1/2}"

  set title "(c) first contact: impulse h {/Symbol S} N^l -> 2 V (COR = 1)"
  set ylabel "impulse [m/s]"
  unset logscale y
  set format y "%g"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", $10)) \
           with points pt 7 ps 0.8 lc rgb stepper_colour[i] notitle, \
       2 * V with lines dt 2 lc rgb "black" title "2 V (Signorini, elastic)"
  set logscale y
  set format y "10^{%L}"

  set title "(d) bounce u_0 = 1 m, T = 2 s, h = 10^{-3} s: error against exact"
  set ylabel "max_l |u^l - u(t_l)| [m]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", finished($15) ? $22 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] notitle, \
       30 / sqrt(x) with lines dt 2 lc rgb "gray40" title "slope -1/2"

  set title "(e) bounce: energy drift v^2/2 - f u + c_N max({/Symbol f} - u, 0)^2/2"
  set ylabel "max_l |E^l - E^0| [m^2/s^2]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", finished($15) ? $5 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] notitle

  set title "(f) ODE steps: bounce (T = 2 s, dashed) and resting contact (T = 0.1 s, solid)"
  set ylabel "ODE steps accepted [1]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", finished($15) ? $21 : NaN)) \
           with linespoints dt 2 pt 6 ps 0.8 lc rgb stepper_colour[i] notitle, \
       for [i = 1:7] stiff using 3:(pick(word(steppers, i), "rest", finished($15) ? $21 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] notitle, \
       1e5 with lines dt 3 lw 1.5 lc rgb "black" title "budget (10^5 steps)"

  set title "(g) resting contact: penetration max({/Symbol f} - u) against 2 |f| / c_N"
  set ylabel "max({/Symbol f} - u) [m]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "rest", finished($15) ? -$16 : NaN)) \
           with points pt 7 ps 0.8 lc rgb stepper_colour[i] notitle, \
       2 * 9.80665 / x with lines dt 2 lc rgb "black" title "2 |f| / c_N"

  # (h): the key of the colours of the steppers.
  unset title
  unset border
  unset tics
  unset xlabel
  unset ylabel
  unset logscale
  unset grid
  set xrange [0:1]
  set yrange [0:1]
  set key center center nobox noopaque noenhanced spacing 1.4 title "GSL stepper of penalty" \
      left reverse Left
  plot for [i = 1:7] NaN with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] \
           title word(steppers, i).(i >= 5 ? " (implicit)" : " (explicit)")
  unset multiplot

  # ---- Figure 4: what the stiff runs cost in time on the processor that ran them ----
  if (format eq "png") {
    set terminal pngcairo size 1300,500 font ",10"
    set output timing.'/stability_stiff_time.png'
  } else {
    set terminal svg size 1300,500 font ",10" dynamic
    set output timing.'/stability_stiff_time.svg'
  }
  set multiplot layout 1,2 margins 0.07, 0.85, 0.12, 0.86 spacing 0.08 title \
      "Normal compliance, resting contact (T = 0.1 s, h = 10^{-3} s): wall time per GSL stepper\non one core of an ".processor
  set border
  set tics
  set grid
  set bmargin
  unset offsets
  set xrange [*:*] noextend
  set autoscale y
  set logscale xy
  set xlabel "c_N [s^{-2}]"
  unset key
  set title "(a) run time"
  set ylabel "wall time [s]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "rest", finished($15) ? $25 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i)
  set title "(b) time per accepted ODE step"
  set ylabel "wall time / ODE steps [s]"
  set key at screen 0.86, 0.5 left center vertical maxcols auto maxrows auto nobox noenhanced \
      spacing 1.4 title "GSL stepper" left reverse Left
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "rest", finished($15) ? $25 / $21 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i)
  unset multiplot
}
