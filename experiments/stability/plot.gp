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

# Outcome colours (the Outcome codes of src/impact/stability.hpp).
array outcome_colour[7] = [0x1a9641, 0xfdd835, 0xd7191c, 0x2b83ba, 0x000000, 0x9e7cc1, 0xd9d9d9]
array outcome_title[7] = ["ok", "inaccurate (error > 1% of the amplitude)", \
    "energy grows where the theory forbids it", "failure reported (did not converge)", \
    "non-finite value caught", "over the work budget (too slow)", "rejected (no COR law)"]
colour(code) = outcome_colour[int(code) + 1]


do for [format in "png svg"] {
  reset
  set style fill solid 1.0 noborder
  # ---- Figure 1: the extreme cases ----
  if (format eq "png") {
    set terminal pngcairo size 2000,700 font ",10"
    set output 'figures/stability_map.png'
  } else {
    set terminal svg size 2000,700 font ",10" dynamic
    set output 'figures/stability_map.svg'
  }
  set multiplot title \
      "Stability map: outcome of each run, method x case x h (T = min(T_{case}, 10^5 h); penalty: c_N = 10^6 s^{-2}, rk8pd, min(T_{case}, 2 10^4 h))"
  set xrange [-9.5:0.5]
  set yrange [18.5:-0.5]
  set xtics -9,1,0
  set xlabel "log_{10} h [s]"
  unset key
  methods = "direct fb_newton moreau_jean exact penalty"
  set size 0.155, 0.93
  do for [m = 1:5] {
    set origin 0.155 * (m - 1), 0.0
    set title word(methods, m) noenhanced
    @set_case_tics
    set ytics noenhanced
    plot results.'/map_cases.dat' index (m - 1) using 3:2:(0.5):(0.5):(colour($4)) \
        with boxxyerror lc rgb variable notitle
  }
  # The key, in a panel of its own.
  set origin 0.78, 0.0
  set size 0.22, 0.93
  unset title
  unset border
  unset tics
  unset xlabel
  set key center center box noenhanced spacing 1.5 left reverse Left
  plot for [c = 1:7] NaN with boxes lc rgb outcome_colour[c] title outcome_title[c]
  set border
  set tics
  unset key
  unset multiplot

  # ---- Figure 2: fb_newton's epsilon, penalty's stepper and c_N ----
  if (format eq "png") {
    set terminal pngcairo size 1800,1000 font ",10"
    set output 'figures/stability_params.png'
  } else {
    set terminal svg size 1800,1000 font ",10" dynamic
    set output 'figures/stability_params.svg'
  }
  set multiplot layout 2,4 title "Stability map: smoothing parameter and normal compliance"
  set xrange [-9.5:0.5]
  set xtics -9,1,0
  set xlabel "log_{10} h [s]"
  set ylabel "log_{10} {/Symbol e}"
  set yrange [-15.5:-1.5]
  set ytics -15,1,-2
  set title "fb\\_newton: bounce from u_0 = 1 m, COR = 1"
  plot results.'/map_eps.dat' index 0 using 3:2:(0.5):(0.5):(colour($4)) \
      with boxxyerror lc rgb variable notitle
  set title "fb\\_newton: resting contact, u_0 = {/Symbol f}, v_0 = 0"
  plot results.'/map_eps.dat' index 1 using 3:2:(0.5):(0.5):(colour($4)) \
      with boxxyerror lc rgb variable notitle

  # The key again, in the last panel of the first row.
  set multiplot next
  unset title
  unset border
  unset tics
  unset xlabel
  unset ylabel
  set key center center box noenhanced spacing 1.5 left reverse Left
  plot for [c = 1:7] NaN with boxes lc rgb outcome_colour[c] title outcome_title[c]
  set border
  set tics
  unset key

  set xrange [1.5:12.5]
  set xtics 2,1,12
  set xlabel "log_{10} c_N [s^{-2}]"
  set ylabel "GSL stepper"
  set yrange [-0.5:6.5]
  @set_stepper_tics
  set ytics noenhanced
  set title "penalty: bounce from u_0 = 1 m, h = 10^{-3} s"
  plot results.'/map_stiff.dat' index 0 using 3:2:(0.5):(0.5):(colour($4)) \
      with boxxyerror lc rgb variable notitle
  set title "penalty: resting contact, h = 10^{-3} s"
  plot results.'/map_stiff.dat' index 1 using 3:2:(0.5):(0.5):(colour($4)) \
      with boxxyerror lc rgb variable notitle

  set xrange [-6.5:-0.5]
  set xtics -6,1,-1
  set xlabel "log_{10} h [s]"
  set yrange [1.5:12.5]
  set ytics 2,1,12
  set ylabel "log_{10} c_N [s^{-2}]"
  do for [i = 1:2] {
    set title sprintf("penalty %s: resting contact", word("rk8pd msbdf", i))
    plot results.'/map_penalty.dat' index (i - 1) using 3:2:(0.5):(0.5):(colour($4)) \
        with boxxyerror lc rgb variable notitle
  }
  unset multiplot

  # ---- Figure 3: penalty as c_N grows ----
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
      "Normal compliance N = c_N max({/Symbol f} - u, 0) as c_N grows: the Signorini limit (Lemma 5's point of view) and the cost per GSL stepper"
  set xrange [50:2e12]
  set autoscale y
  set xtics auto enhanced
  set ytics auto enhanced
  set logscale xy
  set format x "10^{%L}"
  set format y "10^{%L}"
  set xlabel "c_N [s^{-2}]"
  set grid
  set key top right
  V = sqrt(2 * 9.80665)

  set title "first contact, impact speed V = 4.43 m/s: penetration depth (the steppers agree)"
  set key bottom left
  set ylabel "max({/Symbol f} - u) [m]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", $6)) \
           with points pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i), \
       stiff using 3:(pick("rk8pd", "bounce", $7)) with lines lc rgb "black" \
           title "closed form", V / sqrt(x) with lines dt 2 lc rgb "gray" title "V / sqrt(c_N)"

  set title "first contact: duration"
  set ylabel "contact duration [s]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", $8)) \
           with points pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i), \
       stiff using 3:(pick("rk8pd", "bounce", $9)) with lines lc rgb "black" \
           title "closed form", pi / sqrt(x) with lines dt 2 lc rgb "gray" title "{/Symbol p} / sqrt(c_N)"

  set title "first contact: impulse h {/Symbol S} N^l -> 2 V (COR = 1)"
  set key top right
  set ylabel "impulse [m/s]"
  unset logscale y
  set format y "%g"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", $10)) \
           with points pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i), \
       2 * V with lines dt 2 lc rgb "black" title "2 V (Signorini, elastic)"
  set logscale y
  set format y "10^{%L}"

  set title "bounce u_0 = 1 m, T = 2 s, h = 10^{-3} s: error against exact"
  set key bottom left
  set ylabel "max_l |u^l - u(t_l)| [m]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", finished($15) ? $22 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i), \
       30 / sqrt(x) with lines dt 2 lc rgb "gray" title "slope -1/2"

  set title "bounce: energy drift v^2/2 - f u + c_N max({/Symbol f} - u, 0)^2/2"
  set key bottom right
  set ylabel "max_l |E^l - E^0| [m^2/s^2]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", finished($15) ? $5 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i)

  set title "ODE steps: bounce (T = 2 s, dashed) and resting contact (T = 0.1 s, solid)"
  set key top left
  set ylabel "ODE steps accepted"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "bounce", finished($15) ? $21 : NaN)) \
           with linespoints dt 2 pt 6 ps 0.8 lc rgb stepper_colour[i] notitle, \
       for [i = 1:7] stiff using 3:(pick(word(steppers, i), "rest", finished($15) ? $21 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i), \
       1e5 with lines dt 3 lc rgb "black" title "budget"

  set title "resting contact: penetration max({/Symbol f} - u) against 2 |f| / c_N"
  set key bottom left
  set ylabel "max({/Symbol f} - u) [m]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "rest", finished($15) ? -$16 : NaN)) \
           with points pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i), \
       2 * 9.80665 / x with lines dt 2 lc rgb "black" title "2 |f| / c_N"
  unset multiplot

  # ---- Figure 4: what the stiff runs cost in time on this machine ----
  if (format eq "png") {
    set terminal pngcairo size 1200,500 font ",10"
    set output timing.'/stability_stiff_time.png'
  } else {
    set terminal svg size 1200,500 font ",10" dynamic
    set output timing.'/stability_stiff_time.svg'
  }
  set multiplot layout 1,2 title \
      "Normal compliance, resting contact (T = 0.1 s, h = 10^{-3} s): wall time per GSL stepper on this machine"
  set key top left
  set title "run time"
  set ylabel "wall time [s]"
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "rest", finished($15) ? $25 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i)
  set title "time per accepted ODE step (colours as on the left)"
  set ylabel "wall time / ODE steps [s]"
  unset key
  plot for [i = 1:7] stiff using 3:(pick(word(steppers, i), "rest", finished($15) ? $25 / $21 : NaN)) \
           with linespoints pt 7 ps 0.8 lc rgb stepper_colour[i] title word(steppers, i)
  unset multiplot
}
