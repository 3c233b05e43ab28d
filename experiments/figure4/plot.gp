# Figure 4 (Section 5.2, f = -9.80665 m/s^2, u0 = 5 m, v0 = -1 m/s, h = 1e-3 s): left column
# without COR, right column with COR = 0.75; rows u, v, N, E. Thick blue: direct (5-1); dashed
# orange: fb_newton (5-3); thin black: the exact solution on the same grid (elastic without COR,
# Zeno rest at t_inf with COR). N (a force per unit mass; the row at t_l carries N^{l-1}; for
# direct and fb_newton the paper's N^l of (4-3), the channel N_scheme, as in Figure 3) is drawn
# as impulses on a log scale so that the impact spikes (~2 V / h) and the resting force (~|f|) show
# together. Titles give max_l |direct - fb_newton| and the rest times (labels.gp, exp_figure4).
# Second figure, figure4_h_sweep: energy loss, mean energy, rest time and impact count over 121
# step sizes 1e-5 <= h <= 1e-2, and the rest times of u0 moved by up to 200 ulps at h = 1e-3.
# Third figure, figure4_readings: without COR, u(t) of direct with (5-1) in closed form and as
# printed, and the rest-time distributions of both arithmetics over the ensemble; the energy
# change of the contact step of a particle pushed away from the floor (f > 0) over h.
# Usage: gnuplot -e "results='results/figure4'" experiments/figure4/plot.gp
if (!exists("results")) results = 'results/figure4'
load results.'/labels.gp'
set datafile separator ','
csv(scene, method) = sprintf('%s/%s_%s.csv', results, scene, method)
f = -9.80665

blue = "#0072B2"
orange = "#E69F00"
green = "#009E73"
purple = "#CC79A7"

# The vector copy is a PDF: 10^4-point curves in 12 panels make an SVG of several MB.
set style textbox opaque noborder
do for [format in "png pdf"] {
  if (format eq "png") {
    set terminal pngcairo size 1200,1300 font ",10"
    set output 'figures/figure4.png'
  } else {
    set terminal pdfcairo size 8in,8.7in font ",7"
    set output 'figures/figure4.pdf'
  }
  set multiplot layout 4,2 columnsfirst title \
      "Figure 4: f = -9.80665 m/s^2, u_0 = 5 m, v_0 = -1 m/s, h = 10^{-3} s; direct vs fb\\_newton vs exact"
  set grid
  set xrange [*:*] noextend
  set offsets 0, 0, graph 0.05, graph 0.05
  set xtics 1
  set xlabel "t [s]"
  # Each key right of its panel, in a margin of the same width everywhere, so the panels line up.
  set rmargin 30
  set key outside right top box opaque noenhanced

  do for [scene in "no_cor cor075"] {
    label = (scene eq "no_cor") ? "no COR" : "COR = 0.75"
    rest_d = value('rest_'.scene.'_direct'); rest_f = value('rest_'.scene.'_fb_newton')
    exact_rest = (scene eq "no_cor") ? "exact: never" : sprintf("exact: t_{inf} = %.4f s", zeno)

    set title sprintf("%s: displacement\nrest at %.3f s (direct), %.3f s (fb\\_newton); %s", \
                      label, rest_d, rest_f, exact_rest)
    set ylabel "u(t) [m]"
    set autoscale y
    # Dotted: where direct rests; without COR, dashed: the paper's rest "at around t = 7.5".
    set arrow 1 from rest_d, graph 0 to rest_d, graph 1 nohead dt 3 lc rgb blue
    if (scene eq "no_cor") {
      set arrow 2 from 7.5, graph 0 to 7.5, graph 1 nohead dt 2 lw 1.5 lc rgb "black"
    }
    plot csv(scene, 'direct') skip 1 using 1:2 with lines lw 3 lc rgb blue title "direct", \
         csv(scene, 'fb_newton') skip 1 using 1:2 with lines lw 2 dt 2 lc rgb orange \
           title "fb_newton", \
         csv(scene, 'exact') skip 1 using 1:2 with lines lw 1 lc rgb "black" title "exact", \
         NaN with lines dt 3 lc rgb blue title "direct rests", \
         NaN with lines dt 2 lw 1.5 lc rgb "black" \
           title (scene eq "no_cor" ? "paper: rest ~7.5 s" : "")
    unset arrow 1
    unset arrow 2

    set title sprintf("%s: velocity, max|direct - fb\\_newton| = %.2g m/s", label, \
                      value('diff_'.scene.'_v'))
    set ylabel "v(t) [m/s]"
    plot csv(scene, 'direct') skip 1 using 1:3 with lines lw 3 lc rgb blue title "direct", \
         csv(scene, 'fb_newton') skip 1 using 1:3 with lines lw 2 dt 2 lc rgb orange \
           title "fb_newton", \
         csv(scene, 'exact') skip 1 using 1:3 with lines lw 1 lc rgb "black" title "exact"

    # Without COR the scheme rests in a period-2 chatter (u = phi, v = +-c, N = |f| -+ 2c/h on
    # alternate steps; README), which at this scale looks like two constant forces: the title
    # says so.
    chatter = (scene eq "no_cor") ? \
        "\nafter rest: period-2 chatter, N = |f| -+ 2c/h (v = -+c)" : ""
    set title sprintf("%s: contact force, max|direct - fb\\_newton| = %.2g m/s^2%s", label, \
                      value('diff_'.scene.'_N'), chatter)
    set ylabel "N(t) [m/s^2] (log scale)"
    set logscale y
    set yrange [1e-1:*]  # fixed range: N below 0.1 m/s^2 (smoothing, round-off) is not what this shows
    set format y "10^{%L}"
    # Impact steps (N > 2 |f|) as impulses; resting and chatter steps (0 < N <= 2 |f|) as dots.
    impact(n) = n > 2 * abs(f) ? n : NaN
    resting(n) = n > 0 && n <= 2 * abs(f) ? n : NaN
    plot csv(scene, 'exact') skip 1 using 1:(impact($4)) with impulses lw 1 lc rgb "black" \
           title "exact", \
         '' skip 1 using 1:(resting($4)) with points pt 7 ps 0.15 lc rgb "black" notitle, \
         csv(scene, 'direct') skip 1 using 1:(impact($4)) with impulses lw 2 lc rgb blue \
           title "direct", \
         '' skip 1 using 1:(resting($4)) with points pt 7 ps 0.15 lc rgb blue notitle, \
         csv(scene, 'fb_newton') skip 1 using 1:(impact($4)) with points pt 6 ps 0.6 \
           lc rgb orange title "fb_newton", \
         '' skip 1 using 1:(resting($4)) with points pt 7 ps 0.1 lc rgb orange notitle, \
         abs(f) with lines dt 2 lw 1 lc rgb "gray30" title "|f| (resting force)"
    unset logscale y
    set format y "%g"

    set title sprintf("%s: energy, max|direct - fb\\_newton| = %.2g J/kg", label, \
                      value('diff_'.scene.'_E'))
    set ylabel "E(t) = v^2/2 - f u [J/kg]"
    set yrange [0:*]  # fixed range: energy from 0, so that a loss reads as a share of E(0)
    plot csv(scene, 'direct') skip 1 using 1:5 with lines lw 3 lc rgb blue title "direct", \
         csv(scene, 'fb_newton') skip 1 using 1:5 with lines lw 2 dt 2 lc rgb orange \
           title "fb_newton", \
         csv(scene, 'exact') skip 1 using 1:5 with lines lw 1 lc rgb "black" title "exact"
  }
  unset multiplot
  set rmargin
  set output
}

sweep = results.'/h_sweep.csv'
ensemble = results.'/ensemble.csv'
set datafile columnheaders
col(name) = column(name)
zeno_error(name) = abs(column(name) - zeno)

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1200,1350 font ",10"
    set output 'figures/figure4_h_sweep.png'
  } else {
    set terminal svg size 1200,1350 font ",10" dynamic
    set output 'figures/figure4_h_sweep.svg'
  }
  set multiplot layout 3,2 rowsfirst title \
      "Figure 4 over 121 step sizes h (f = -9.80665 m/s^2, u_0 = 5 m, v_0 = -1 m/s, T = 10 s)"
  set grid
  set logscale x
  set xrange [*:*] noextend
  set xtics auto
  set format x "10^{%L}"
  set xlabel "h [s]" offset 0, 0.4
  set bmargin 9
  set key below maxrows 4 nobox noenhanced title " "
  set arrow 9 from 1e-3, graph 0 to 1e-3, graph 1 nohead dt 3 lc rgb "gray50"

  set title "(a) no COR: energy lost, E(0) - E(T) and at the first impact (exact: 0)"
  set logscale y
  set yrange [*:*] noextend
  set offsets 0, 0, graph 0.08, graph 0.05
  set format y "%g"
  set ylabel "energy loss [J/kg] (log scale)"
  plot sweep using 1:(col("no_cor_direct_energy_loss")) with points pt 6 lc rgb blue \
         title "direct, E(0) - E(T)", \
       sweep using 1:(col("no_cor_fb_newton_energy_loss")) with points pt 2 lc rgb orange \
         title "fb_newton, E(0) - E(T)", \
       sweep using 1:(col("no_cor_direct_first_impact_loss")) with linespoints pt 7 ps 0.6 \
         lw 1 lc rgb green title "direct, first impact", \
       sweep using 1:(col("no_cor_fb_newton_first_impact_loss")) with points pt 1 ps 0.8 \
         lc rgb purple title "fb_newton, first impact", \
       energy0 with lines lc rgb "black" dt 2 title sprintf("E(0) = %.3f", energy0)
  unset logscale y
  unset offsets

  set title "(b) no COR: flatness of E(t), the mean of E^l over [0, T] / E(0) (exact: 1)"
  set yrange [0:*]  # fixed range: a share of E(0), drawn from 0
  set ylabel "mean E / E(0) [1]"
  plot sweep using 1:(col("no_cor_direct_energy_mean") / energy0) with linespoints pt 6 \
         lw 1 lc rgb blue title "direct", \
       sweep using 1:(col("no_cor_fb_newton_energy_mean") / energy0) with points pt 2 \
         lc rgb orange title "fb_newton", \
       1 with lines lc rgb "black" title "exact (elastic)"

  # The 401 runs from u0 moved by up to 200 ulps at h = 1e-3 as one box: their quartiles and
  # median, whiskers to their least and largest rest time (figure4_readings (b) is their histogram).
  set datafile missing "nan"
  stats ensemble using (col("no_cor_direct")) name "ULPS" nooutput
  set datafile missing
  set title "(c) no COR: rest time (exact: never rests)"
  set yrange [0:*]  # fixed range: a time from the start, drawn from 0
  set ylabel "rest time [s]"
  set style fill empty
  set boxwidth 0.08
  plot sweep using 1:(col("no_cor_direct_rest_time")) with linespoints pt 6 lw 1 \
         lc rgb blue title "direct", \
       sweep using 1:(col("no_cor_fb_newton_rest_time")) with points pt 2 lc rgb orange \
         title "fb_newton", \
       '+' using (1e-3):(ULPS_lo_quartile):(ULPS_min):(ULPS_max):(ULPS_up_quartile):(0.15e-3) \
         every ::0::0 with candlesticks whiskerbars lw 2 lc rgb "black" \
         title sprintf("direct, h = 1e-3, %d runs with u0 moved by <= 200 ulps: quartiles, min, max", ULPS_records), \
       '+' using (1e-3):(ULPS_median):(ULPS_median):(ULPS_median):(ULPS_median):(0.15e-3) \
         every ::0::0 with candlesticks lw 2 lc rgb "black" notitle, \
       7.5 with lines lc rgb "black" dt 2 title "paper: 'comes to a stop at around t = 7.5'"

  set title sprintf("(d) COR = 0.75: rest time against the exact Zeno time %.4f s", zeno)
  set autoscale y
  plot sweep using 1:(col("cor075_direct_rest_time")) with linespoints pt 6 lw 1 \
         lc rgb blue title "direct", \
       sweep using 1:(col("cor075_fb_newton_rest_time")) with points pt 2 lc rgb orange \
         title "fb_newton", \
       zeno with lines lc rgb "black" title "exact t_inf = t_1 + 2 COR V_1 / (|f| (1 - COR))"

  set title sprintf("(e) COR = 0.75: rest-time error |t_{rest} - t_{inf}| (fitted order %.2f)", \
                    order_direct)
  set logscale y
  set autoscale y
  set format y "10^{%L}"
  set ylabel "|t_{rest} - t_{inf}| [s]"
  plot sweep using 1:(zeno_error("cor075_direct_rest_time")) with points pt 6 lc rgb blue \
         title "direct", \
       sweep using 1:(zeno_error("cor075_fb_newton_rest_time")) with points pt 2 \
         lc rgb orange title "fb_newton", \
       2.5 * x * log(9.95 / (x * 9.80665 / 2)) / log(4.0 / 3) with lines lw 2 lc rgb "#D55E00" \
         title "2.5 h K(h), K = ln(2 V_1/(h |f|)) / ln(1/COR)", \
       10 * x with lines lc rgb "gray50" dt 3 title "10 h (order 1)"
  unset logscale y
  set format y "%g"

  set title "(f) impacts before rest"
  set yrange [0:*]  # fixed range: counts, drawn from 0
  set ylabel "impacts [1]"
  plot sweep using 1:(col("cor075_direct_impacts")) with linespoints pt 6 lw 1 lc rgb blue \
         title "direct, COR = 0.75", \
       sweep using 1:(col("cor075_fb_newton_impacts")) with points pt 2 lc rgb orange \
         title "fb_newton, COR = 0.75", \
       sweep using 1:(col("no_cor_direct_impacts")) with linespoints pt 7 ps 0.6 lw 1 \
         lc rgb green title "direct, no COR", \
       sweep using 1:(col("no_cor_fb_newton_impacts")) with points pt 1 lc rgb purple \
         title "fb_newton, no COR"
  unset multiplot
  unset arrow 9
  set bmargin
  set output
}

# The readings figure. Histogram of rest times in 0.1 s bins, the two arithmetics side by side in
# each bin. A member still bouncing at T has no rest time: it is counted in the title and binned
# at -1, off the axis (an undefined value would cut the data in two, and smooth frequency would
# then count each part on its own: two boxes in one bin).
bin(t) = 0.1 * floor(t / 0.1) + 0.05
rest_bin(name) = (column(name) == column(name)) ? bin(column(name)) : -1
set datafile missing "nan"

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1100,1300 font ",10"
    set output 'figures/figure4_readings.png'
  } else {
    set terminal svg size 1100,1300 font ",10" dynamic
    set output 'figures/figure4_readings.svg'
  }
  unset logscale
  set format x "%g"
  set format y "%g"
  set xtics auto
  set multiplot layout 3,1 title \
      "Figure 4 without COR (h = 10^{-3} s): the rest time depends on how (5-1) is rounded"
  set grid
  set key outside right top vertical box opaque noenhanced
  set datafile columnheaders

  set title sprintf("(a) u(t), direct: closed form rests at %.3f s, (5-1) as printed at %.3f s", \
                    rest_no_cor_direct, rest_no_cor_direct_paper)
  set xrange [*:*] noextend
  set xlabel "t [s]" offset 0, 0
  set ylabel "u(t) [m]"
  set autoscale y
  set arrow 1 from rest_no_cor_direct, graph 0 to rest_no_cor_direct, graph 1 nohead dt 3 \
      lc rgb blue
  set arrow 2 from rest_no_cor_direct_paper, graph 0 to rest_no_cor_direct_paper, graph 1 nohead \
      dt 3 lc rgb orange
  plot csv('no_cor', 'direct') using 1:2 with lines lw 3 lc rgb blue title "closed form", \
       csv('no_cor', 'direct_paper') using 1:2 with lines lw 2 dt 2 lc rgb orange \
         title "as printed", \
       csv('no_cor', 'exact') using 1:2 with lines lw 1 lc rgb "black" title "exact (elastic)"
  unset arrow 1
  unset arrow 2

  set title sprintf("(b) rest times of 401 runs with u0 moved by <= 200 ulps\nat >= 7.5 s or still bouncing at T = 10 s: closed form %d, as printed %d (%d bouncing)", \
                    late_closed_form, late_paper, bouncing_paper)
  # The rest times of both arithmetics lie in 5..10 s; a run still bouncing at T is binned at -1.
  set xrange [5:10]  # fixed range: the rest times lie in 5..10 s, the bouncing runs binned at -1 fall outside
  set xlabel "rest time [s] (0.1 s bins)"
  set ylabel "runs [1]"
  set yrange [0:*]  # fixed range: counts, drawn from 0
  set style fill solid 0.8 noborder
  set boxwidth 0.045 absolute
  set arrow 3 from 7.5, graph 0 to 7.5, graph 1 nohead dt 2 lw 2 lc rgb "black"
  plot ensemble using (rest_bin("no_cor_direct") - 0.025):(1) smooth frequency with boxes \
         lc rgb blue title "closed form", \
       ensemble using (rest_bin("no_cor_direct_paper") + 0.025):(1) smooth frequency with boxes \
         lc rgb orange title "as printed", \
       NaN with lines dt 2 lw 2 lc rgb "black" title "paper: 'around t = 7.5'"
  unset arrow 3
  set style fill empty

  set title sprintf("(c) energy change of the contact step, u_0 = 0.01 m, v_0 = -1 m/s, f = +9.80665 m/s^2 (fitted order of the rise %.2f)", contact_order)
  set logscale xy
  set xrange [*:*] noextend
  set autoscale y
  set format x "10^{%L}"
  set format y "10^{%L}"
  set xlabel "h [s]"
  set ylabel "|E^{l+1} - E^l| [J/kg]"
  contact = results.'/contact_energy.csv'
  plot contact using 1:(col("cor1_change")) with linespoints pt 7 lc rgb "#D55E00" \
         title "COR = 1: rise", \
       contact using 1:(-col("cor075_change")) with linespoints pt 6 lc rgb green \
         title "COR = 0.75: fall", \
       9.80665 * x with lines dt 2 lc rgb "black" title "f h (bound of the rise)"
  unset multiplot
  set output
}
