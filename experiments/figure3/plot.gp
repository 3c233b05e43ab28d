# Figure 3 (Section 5.2, f = 0, u0 = 5 m, v0 = -1 m/s, h = 1e-3 s): left column without COR, right
# column with COR = 0.75; rows u, v, N, E. Thick blue: direct (5-1); dashed orange: fb_newton
# (5-3); thin black: the exact solution sampled on the same grid. N is a force per unit mass, the
# row at t_l carries N^{l-1}, drawn as impulses so that the one-step spike of height 2/h is
# visible: for direct and fb_newton the paper's N^l of (4-3) (the channel N_scheme, which Newton's
# law does not change: with COR its impulse 2 |v| is not the floor's (1 + COR) |v|, which the
# channel N carries), for exact the impulse of the step ending at t_l divided by h. Panel titles give
# max_l |direct - fb_newton| (from labels.gp, written by exp_figure3).
# Second figure: the energy kept by the one impact, E(T)/E(0), against h.
# Usage: gnuplot -e "results='results/figure3'" experiments/figure3/plot.gp
if (!exists("results")) results = 'results/figure3'
load results.'/labels.gp'
set datafile separator ','
csv(scene, method) = sprintf('%s/%s_%s.csv', results, scene, method)

blue = "#0072B2"
orange = "#E69F00"

# The vector copy is a PDF: 10^4-point curves in 12 panels make an SVG of several MB.
do for [format in "png pdf"] {
  if (format eq "png") {
    set terminal pngcairo size 1200,1300 font ",10"
    set output 'figures/figure3.png'
  } else {
    set terminal pdfcairo size 8in,8.7in font ",7"
    set output 'figures/figure3.pdf'
  }
  set multiplot layout 4,2 columnsfirst title \
      "Figure 3: f = 0, u_0 = 5 m, v_0 = -1 m/s, h = 10^{-3} s; direct vs fb\\_newton vs exact"
  set grid
  set xrange [*:*] noextend
  set offsets 0, 0, graph 0.05, graph 0.05
  set xtics 1
  # Each key right of its panel, in a margin of the same width everywhere, so the panels line up.
  set rmargin 25
  set key outside right top box opaque noenhanced

  do for [scene in "no_cor cor075"] {
    label = (scene eq "no_cor") ? "no COR" : "COR = 0.75"
    du = value('diff_'.scene.'_u'); dv = value('diff_'.scene.'_v')
    dN = value('diff_'.scene.'_N'); dE = value('diff_'.scene.'_E')

    set title sprintf("%s: displacement, max|direct - fb\\_newton| = %.2g m", label, du)
    set ylabel "u(t) [m]"
    set autoscale y
    set xlabel "t [s]"
    plot csv(scene, 'direct') skip 1 using 1:2 with lines lw 3 lc rgb blue title "direct", \
         csv(scene, 'fb_newton') skip 1 using 1:2 with lines lw 2 dt 2 lc rgb orange \
           title "fb_newton", \
         csv(scene, 'exact') skip 1 using 1:2 with lines lw 1 lc rgb "black" title "exact"

    set title sprintf("%s: velocity, max|direct - fb\\_newton| = %.2g m/s", label, dv)
    set ylabel "v(t) [m/s]"
    plot csv(scene, 'direct') skip 1 using 1:3 with lines lw 3 lc rgb blue title "direct", \
         csv(scene, 'fb_newton') skip 1 using 1:3 with lines lw 2 dt 2 lc rgb orange \
           title "fb_newton", \
         csv(scene, 'exact') skip 1 using 1:3 with lines lw 1 lc rgb "black" title "exact"

    set title sprintf("%s: contact force, max|direct - fb\\_newton| = %.2g m/s^2", label, dN)
    set ylabel "N(t) [m/s^2]"
    set yrange [0:*]  # fixed range: a contact force is drawn from 0
    # With COR the spike is the same as without (the landing step has N^{4999} = 0 and is not yet
    # an impact, so the COR acts on the next step), while the exact impulse is (1 + COR) V.
    if (scene eq "cor075") {
      set label 1 "direct, fb\\_newton: N = 2/h = 2000\nat t = 5.001 s, as without COR\n(impulse h N = 2 m/s); exact:\n(1 + COR) V / h = 1750 at t = 5 s" \
          at 5.3, graph 0.55 left font ",9"
    }
    plot csv(scene, 'direct') skip 1 using 1:4 with impulses lw 3 lc rgb blue title "direct", \
         csv(scene, 'fb_newton') skip 1 using 1:($4 > 0 ? $4 : NaN) with points pt 6 ps 1.2 \
           lc rgb orange title "fb_newton, N > 0", \
         csv(scene, 'exact') skip 1 using 1:4 with impulses lw 1 lc rgb "black" \
           title "exact, (1+e) V/h"
    unset label 1

    set title sprintf("%s: energy, max|direct - fb\\_newton| = %.2g J/kg", label, dE)
    set ylabel "E(t) = v^2/2 - f u [J/kg]"
    set yrange [0:*]  # fixed range: energy from 0, so that a loss reads as a share of E(0)
    plot csv(scene, 'direct') skip 1 using 1:5 with lines lw 3 lc rgb blue title "direct", \
         csv(scene, 'fb_newton') skip 1 using 1:5 with lines lw 2 dt 2 lc rgb orange \
           title "fb_newton", \
         csv(scene, 'exact') skip 1 using 1:5 with lines lw 1 lc rgb "black" title "exact"
  }
  unset multiplot
  set rmargin
  unset offsets
  set output
}

# The energy kept by the impact against h (no COR): 1 only when t* = 5 is a grid point.
sweep = results.'/h_sweep.csv'
do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 900,500 font ",10"
    set output 'figures/figure3_h_sweep.png'
  } else {
    set terminal svg size 900,500 font ",10" dynamic
    set output 'figures/figure3_h_sweep.svg'
  }
  set title "Figure 3 left (f = 0, no COR): energy kept by the impact, E(T)/E(0), at 201 step sizes h"
  set grid
  set logscale x
  set xrange [*:*] noextend
  set autoscale y
  set offsets 0, 0, graph 0.12, graph 0.05
  set xtics auto
  set format x "10^{%L}"
  set ytics 0.2
  set xlabel "h [s]"
  set ylabel "E(T) / E(0) [1]"
  set key below maxrows 2 nobox noenhanced title " "
  set arrow 1 from 1e-3, graph 0 to 1e-3, graph 1 nohead dt 2 lc rgb "gray40"
  set label 1 "paper's h = 10^{-3}: t* = 5 on the grid" at 0.95e-3, first 1.1 right tc rgb "gray30"
  plot sweep skip 1 using 1:3 with points pt 6 ps 1.2 lc rgb blue title "direct", \
       sweep skip 1 using 1:4 with points pt 2 ps 1.0 lc rgb orange title "fb_newton", \
       sweep skip 1 using 1:5 with points pt 7 ps 0.4 lc rgb "black" \
         title "(1 - 2 theta)^2, theta = (u^l - phi)/(h |v^l|)", \
       1 with lines lw 1 lc rgb "black" dt 3 title "exact (elastic)"
  unset arrow 1
  unset label 1
  set output
}
