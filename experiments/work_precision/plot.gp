# Work-precision diagrams. Reads results/work_precision/ (exp_work_precision), writes
#   figures/work_precision.{png,svg}          the main diagram: sup |u_h - u| against CPU time on
#                                             each scene, and the mechanism of direct's stall
#   figures/work_precision_<scene>.{png,svg}  every error measure against CPU time (top row) and
#                                             against h (bottom row, the time-steppers)
# Errors below 1e-16 (rounding, or an exactly reproduced quantity) are drawn at 1e-16.
# Usage: gnuplot -e "results='results/work_precision'" experiments/work_precision/plot.gp
if (!exists("results")) results = 'results/work_precision'
load results.'/curves.gp'
set datafile separator ','

file(scene, c) = results.'/curves/'.scene.'.'.c.'.csv'
shown(x) = x < 1e-16 ? 1e-16 : x
is_penalty(c) = strstrt(c, "penalty") == 1
col(c) = c eq "direct" ? "#0072B2" : c eq "fb_newton" ? "#56B4E9" : c eq "moreau_jean" ? "#009E73" : \
         c eq "siconos" ? "#000000" : strstrt(c, "rk8pd") ? "#CC79A7" : "#D55E00"
dash(c) = c eq "fb_newton" ? 2 : c eq "siconos" ? 3 : is_penalty(c) ? 4 : 1
point(c) = c eq "direct" ? 7 : c eq "fb_newton" ? 6 : c eq "moreau_jean" ? 5 : c eq "siconos" ? 4 : \
           strstrt(c, "1e4") ? 8 : strstrt(c, "1e6") ? 10 : 12
tit(c) = c eq "direct" ? "direct (5-1)" : c eq "fb_newton" ? "fb\\_newton (5-3)" : \
         c eq "moreau_jean" ? "moreau\\_jean" : c eq "siconos" ? "Siconos MoreauJeanOSI + LCP" : \
         "penalty ".c[9:13]." c_N = ".c[17:]

# The error measures: column in the curve files and axis label.
measures = "sup_u l1_v energy_end first_impact"
mcol(m) = m eq "sup_u" ? 5 : m eq "l1_v" ? 6 : m eq "energy_end" ? 7 : 8
mlabel(m) = m eq "sup_u" ? "max_l |u^l - u(t_l)| [m]" : m eq "l1_v" ? "h {/Symbol S}_l |v^l - v(t_l)| [m]" : \
            m eq "energy_end" ? "|E^n - E(T)| [m^2/s^2]" : "|t_{1,h} - t_1| [s]"
mtitle(m) = m eq "sup_u" ? "sup-norm of u" : m eq "l1_v" ? "L^1 norm of v" : \
            m eq "energy_end" ? "energy at T" : "first impact time"

set style data linespoints
set logscale xy
set format x "10^{%L}"
set format y "10^{%L}"
set grid

do for [format in "png svg"] {
  # --- the main diagram ---
  if (format eq "png") {
    set terminal pngcairo size 1500,950 font ",10"
    set output 'figures/work_precision.png'
  } else {
    set terminal svg size 1500,950 font ",10" dynamic
    set output 'figures/work_precision.svg'
  }
  set multiplot layout 2,3 title "Work against precision: sup-norm error of u against CPU time of the solve (T = 10 s, minimum over repetitions)"
  set xlabel "CPU time of the solve [s]"
  set ylabel mlabel("sup_u")
  set yrange [1e-16:100]
  panel = 0
  do for [scene in scenes] {
    panel = panel + 1
    set title sprintf("(%c) %s", 96 + panel, value('title_'.scene))
    if (panel == 1 || panel == 3) {
      set key bottom left font ",8" box opaque
    } else {
      unset key
    }
    plot for [c in value('curves_'.scene)] file(scene, c) skip 1 using 3:(shown(column(5))) \
         lc rgb col(c) dt dash(c) pt point(c) ps 0.8 lw 1.5 title tit(c)
  }
  # (f) why direct stalls without COR: the energy it loses at an off-grid impact.
  set title "(f) direct, no COR, off-grid impact: the energy lost does not fall with h"
  set xlabel "step h [s]"
  set ylabel "|E^n - E(T)| [m^2/s^2]"
  unset logscale y
  set format y "%g"
  set yrange [0:0.7]
  set key top left Left reverse font ",9" box opaque
  plot results.'/mechanism.csv' skip 1 using 1:4 with points pt 6 ps 2 lc rgb "#999999" \
           title "predicted 2{/Symbol q}(1-{/Symbol q})v^2, {/Symbol q} = frac({/Symbol p}/h)", \
       '' skip 1 using 1:5 with points pt 7 ps 0.9 lc rgb "#0072B2" title "measured"
  unset multiplot
  set logscale y
  set format y "10^{%L}"

  # --- one figure per scene: every measure against CPU time and against h ---
  do for [scene in scenes] {
    if (format eq "png") {
      set terminal pngcairo size 1900,900 font ",10"
      set output 'figures/work_precision_'.scene.'.png'
    } else {
      set terminal svg size 1900,900 font ",10" dynamic
      set output 'figures/work_precision_'.scene.'.svg'
    }
    set multiplot layout 2,4 title "Work against precision, ".value('title_'.scene)." (T = 10 s)"
    set yrange [1e-16:*]
    panel = 0
    do for [m in measures] {
      panel = panel + 1
      set title sprintf("(%c) %s against CPU time", 96 + panel, mtitle(m))
      set xlabel "CPU time of the solve [s]"
      set ylabel mlabel(m)
      if (panel == 1) {
        set key bottom left font ",8" box opaque
      } else {
        unset key
      }
      plot for [c in value('curves_'.scene)] file(scene, c) skip 1 \
           using 3:(shown(column(mcol(m)))) lc rgb col(c) dt dash(c) pt point(c) ps 0.8 lw 1.5 \
           title tit(c)
    }
    do for [m in measures] {
      panel = panel + 1
      set title sprintf("(%c) %s against the step h", 96 + panel, mtitle(m))
      set xlabel "step h [s]"
      set ylabel mlabel(m)
      unset key
      plot for [c in value('curves_'.scene)] file(scene, c) skip 1 \
           using (is_penalty(c) ? NaN : column(1)):(shown(column(mcol(m)))) \
           lc rgb col(c) dt dash(c) pt point(c) ps 0.8 lw 1.5 title tit(c)
    }
    unset multiplot
  }
}
