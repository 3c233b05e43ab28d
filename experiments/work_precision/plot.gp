# Work-precision diagrams. Reads results/work_precision/ (exp_work_precision), writes to `out`
# (results/figures: CPU times differ from run to run, so `make refresh-timing-figures` copies them
# to figures/):
#   work_precision.{png,svg}          the main diagram: sup |u_h - u| against CPU time on each
#                                     scene, and the mechanism of direct's stall
#   work_precision_forced.{png,svg}   the same on the scenes with a time-dependent force f(t), and
#                                     the chaotic scene's Lyapunov separation with its horizon
#   work_precision_<scene>.{png,svg}  every error measure against CPU time (first row), against h
#                                     (second row, the time-steppers) and, on the scenes penalty,
#                                     event_driven or LSODAR run, against their tolerance (third row)
#   work_precision_located.{png,svg}  direct_located (paper_notes/error_analysis.md) against direct,
#                                     moreau_jean and the cost of exact, on Figures 3 and 4 (COR)
#                                     and the period-1 vibrating table
# Penalty, event_driven and LSODAR run on a fixed grid (h = 1e-3) and sweep their tolerance,
# over which their CPU time hardly moves (it goes to the output steps): such a sweep drawn against
# CPU time is a vertical streak. So the CPU-time panels show the tightest tolerance only, one
# point per curve, and the third row shows the sweep against the tolerance.
# Each panel's y range is that of its data. Errors below 1e-16 (exact, or rounding) are drawn on
# the bottom axis, labelled "< 10^-16", below the decade of the smallest larger error (by 7% of the
# axis, at least half a decade; the tics then start at that decade, so no label crowds it).
# Usage: gnuplot -e "results='results/work_precision'; out='results/figures'" \
#          experiments/work_precision/plot.gp
if (!exists("results")) results = 'results/work_precision'
if (!exists("out")) out = 'results/figures'
load results.'/curves.gp'
set datafile separator ','

file(scene, c) = results.'/curves/'.scene.'.'.c.'.csv'
is_penalty(c) = strstrt(c, "penalty") == 1
# A tolerance sweep on the fixed grid: penalty's, event_driven's and Siconos's LSODAR.
is_tol(c) = is_penalty(c) || c eq "siconos_lsodar" || c eq "event_driven"
col(c) = c eq "direct" ? "#0072B2" : c eq "direct_located" ? "#E41A1C" : c eq "fb_newton" ? "#56B4E9" : c eq "moreau_jean" ? "#009E73" : \
         c eq "siconos" ? "#000000" : c eq "siconos_lsodar" ? "#7F7F7F" : \
         c eq "event_driven" ? "#E69F00" : \
         strstrt(c, "rk8pd") ? "#CC79A7" : "#D55E00"
dash(c) = c eq "fb_newton" ? 2 : c eq "siconos" ? 3 : is_tol(c) ? 4 : 1
# Siconos's Moreau-Jean is moreau_jean's scheme: against h its points lie on moreau_jean's (errors
# equal to 1e-11), so its squares are drawn larger, around them.
psize(c) = c eq "siconos" ? 1.4 : 0.8
point(c) = c eq "direct" ? 7 : c eq "direct_located" ? 3 : c eq "fb_newton" ? 6 : c eq "moreau_jean" ? 5 : c eq "siconos" ? 4 : \
           c eq "siconos_lsodar" ? 9 : c eq "event_driven" ? 13 : strstrt(c, "1e4") ? 8 : strstrt(c, "1e6") ? 10 : 12
tit(c) = c eq "direct" ? "direct (5-1)" : c eq "direct_located" ? "direct\\_located (impact located)" : c eq "fb_newton" ? "fb\\_newton (5-3)" : \
         c eq "moreau_jean" ? "moreau\\_jean" : c eq "siconos" ? "Siconos MoreauJeanOSI + LCP" : \
         c eq "siconos_lsodar" ? "Siconos EventDriven + LsodarOSI" : \
         c eq "event_driven" ? "event\\_driven (GSL rk8pd)" : \
         "penalty ".c[9:13]." c_N = ".c[17:]

# The error measures: column in the curve files and axis label.
measures = "sup_u l1_v energy_end first_impact"
mcol(m) = m eq "sup_u" ? 5 : m eq "l1_v" ? 6 : m eq "energy_end" ? 7 : 8
mlabel(m) = m eq "sup_u" ? "max_l |u^l - u(t_l)| [m]" : m eq "l1_v" ? "h {/Symbol S}_l |v^l - v(t_l)| [m]" : \
            m eq "energy_end" ? "|E^n - E(T)| [m^2/s^2]" : "|t_{1,h} - t_1| [s]"
mtitle(m) = m eq "sup_u" ? "sup-norm of u" : m eq "l1_v" ? "L^1 norm of v" : \
            m eq "energy_end" ? "energy at T" : "first impact time"

# What a panel draws: mode 1 against CPU time (every curve; a tolerance sweep at its tightest
# tolerance), mode 2 against h (the time-steppers), mode 3 against the tolerance (penalty, LSODAR).
tightest = 2e-11
drawn(c) = mode == 1 ? 1 : mode == 2 ? !is_tol(c) : is_tol(c)
row_drawn(c) = mode != 1 || !is_tol(c) || column(2) < tightest
below = 1e-16
# The y value drawn: NaN for a row not drawn, the bottom axis (zero_at) for an error below 1e-16.
yvalue(c, v) = row_drawn(c) ? (v < below ? zero_at : v) : NaN
# The x value drawn: CPU time, h or tolerance (NaN for a curve the panel does not draw).
xvalue(c) = !drawn(c) ? NaN : mode == 1 ? column(3) : mode == 2 ? column(1) : column(2)

# Sets the y range of a panel from its data: scene, mode and mc (the measure's column) given.
# stats takes the axes' current ranges and log scales into account, so they are unset around it.
# (Macros are expanded when a loop is read, so they are all defined here, before the loops.)
y_range = "lo = 1e300; hi = 0; zeros = 0; unset logscale; set autoscale xy; \
  do for [c in value('curves_'.scene)] { if (drawn(c)) { \
    stats file(scene, c) skip 1 using (row_drawn(c) && column(mc) >= below ? column(mc) : 1e300):(row_drawn(c) && column(mc) >= below ? column(mc) : 0) nooutput; \
    lo = STATS_min_x < lo ? STATS_min_x : lo; hi = STATS_max_y > hi ? STATS_max_y : hi; \
    stats file(scene, c) skip 1 using (row_drawn(c) && column(mc) < below ? 1 : 0) nooutput; \
    zeros = zeros + STATS_sum } }; \
  if (hi == 0) { lo = below; hi = 1 }; \
  top = 10**ceil(log10(hi) + 0.2); bottom = 10**floor(log10(lo) - 0.2); \
  if (top / bottom < 100) { bottom = top / 100 }; \
  zero_at = zeros > 0 ? bottom / 10**(0.07 * log10(top / bottom) > 0.5 ? 0.07 * log10(top / bottom) : 0.5) : bottom; \
  set logscale xy; set yrange [zero_at:top]; set ytics autofreq; \
  if (zeros > 0) { set ytics bottom, 10**ceil(log10(top / bottom) / 8); set ytics add ('< 10^{-16}' zero_at) }"
# Draws a panel: the curves as lines and points; penalty against CPU time as points alone.
plot_curves = "plot for [c in value('curves_'.scene)] file(scene, c) skip 1 \
    using (mode == 1 && is_tol(c) ? NaN : xvalue(c)):(yvalue(c, column(mc))) with linespoints \
    lc rgb col(c) dt dash(c) pt point(c) ps psize(c) lw 1.5 notitle, \
  for [c in value('curves_'.scene)] file(scene, c) skip 1 \
    using (mode == 1 && is_tol(c) ? xvalue(c) : NaN):(yvalue(c, column(mc))) with points \
    lc rgb col(c) pt point(c) ps 1.2 notitle"

# Panels placed by hand: `row`, `col` in a grid of nrow x ncol over [gx0, gx1] x [gy0, gy1].
panel_at = "pw = (gx1 - gx0 - (ncol - 1) * gapx) / ncol; ph = (gy1 - gy0 - (nrow - 1) * gapy) / nrow; \
  set lmargin at screen gx0 + (col - 1) * (pw + gapx); set rmargin at screen gx0 + (col - 1) * (pw + gapx) + pw; \
  set tmargin at screen gy1 - (row - 1) * (ph + gapy); set bmargin at screen gy1 - (row - 1) * (ph + gapy) - ph"
# The key of the curves key_curves, titled key_title, in the strip right of the panels, in the
# font key_font.
key_strip = "set lmargin at screen gx1 + 0.005; set rmargin at screen 0.995; set tmargin at screen gy1; \
  set bmargin at screen gy0; unset title; unset border; unset tics; unset xlabel; unset ylabel; \
  unset logscale; unset grid; set xrange [0:1]; set yrange [0:1]; \
  set key inside center center nobox noopaque Left reverse enhanced spacing 1.3 font key_font title key_title; \
  plot for [c in key_curves] NaN with linespoints lc rgb col(c) dt dash(c) pt point(c) ps psize(c) lw 1.5 title tit(c); \
  set border; set tics; set grid; unset key"

# Every curve of the constant-force scenes, in the order of the first scene that has it.
all_curves = ""
do for [scene in constant_scenes] {
  do for [c in value('curves_'.scene)] {
    if (strstrt(" ".all_curves." ", " ".c." ") == 0) { all_curves = all_curves." ".c }
  }
}
# The key's title names the tolerance sweeps the figure draws, and only those.
sweeps_in(curves) = (strstrt(curves, "penalty") ? ", penalty" : "") . \
  (strstrt(curves, "event_driven") ? ", event\\_driven" : "") . (strstrt(curves, "lsodar") ? ", LSODAR" : "")
tolerance_note(curves) = strlen(sweeps_in(curves)) == 0 ? "method" : \
  "method\n(".sweeps_in(curves)[3:].":\non the grid h = 10^{-3} s;\nagainst CPU time one point,\nat the tightest tolerance 10^{-11})\n"
zero_note = "an error below 10^{-16} (exact, or rounding) is drawn on the bottom axis, at < 10^{-16}"

key_font = ",10"
set style data linespoints
set format x "10^{%L}"
set format y "10^{%L}"
unset key

do for [format in "png svg"] {
  # --- the main diagram ---
  if (format eq "png") {
    set terminal pngcairo size 1700,950 font ",10"
    set output out.'/work_precision.png'
  } else {
    set terminal svg size 1700,950 font ",10" dynamic
    set output out.'/work_precision.svg'
  }
  set multiplot title "Work against precision: sup-norm error of u against CPU time of the solve (T = 10 s, minimum over repetitions)\n".zero_note
  nrow = 2; ncol = 3; gx0 = 0.06; gx1 = 0.82; gy0 = 0.08; gy1 = 0.88; gapx = 0.06; gapy = 0.12
  set logscale xy
  set grid
  set xlabel "CPU time of the solve [s]"
  set ylabel mlabel("sup_u")
  mode = 1; mc = mcol("sup_u")
  panel = 0
  do for [scene in constant_scenes] {
    panel = panel + 1
    row = 1 + (panel - 1) / 3; col = 1 + (panel - 1) % 3
    @panel_at
    set title sprintf("(%c) %s", 96 + panel, value('title_'.scene))
    @y_range
    @plot_curves
  }
  # (f) why direct stalls without COR: the energy it loses at an off-grid impact.
  row = 2; col = 3
  @panel_at
  set title "(f) direct, no COR, off-grid:\nthe energy lost does not fall with h"
  set xlabel "step h [s]"
  set ylabel "|E^n - E(T)| [m^2/s^2]"
  unset logscale y
  set format y "%g"
  # fixed range: the loss 2 theta (1 - theta) v^2 is at most v^2/2 = 0.5; the band above holds the key
  set yrange [0:0.7]
  set ytics autofreq
  # key inside: the band above 0.5, which no loss reaches (see the range)
  set key inside top left Left reverse font ",9" box opaque
  plot results.'/mechanism.csv' skip 1 using 1:4 with points pt 6 ps 2 lc rgb "#999999" \
           title "predicted 2{/Symbol q}(1-{/Symbol q})v^2, {/Symbol q} = frac({/Symbol p}/h)", \
       '' skip 1 using 1:5 with points pt 7 ps 0.9 lc rgb "#0072B2" title "measured"
  unset key
  set format y "10^{%L}"
  key_curves = all_curves; key_title = tolerance_note(key_curves)
  @key_strip
  unset multiplot

  # --- the scenes with f(t): sup error against CPU time, and the chaotic scene's horizon ---
  if (strlen(forced_scenes) > 0) {
  if (format eq "png") {
    set terminal pngcairo size 1500,1000 font ",10"
    set output out.'/work_precision_forced.png'
  } else {
    set terminal svg size 1500,1000 font ",10" dynamic
    set output out.'/work_precision_forced.svg'
  }
  set multiplot title "Work against precision with a time-dependent force f(t): sup-norm error of u against CPU time of the solve\n(reference: exact for the vibrating table, event\\_driven for the expression; ".zero_note.")"
  nrow = 2; ncol = 2; gx0 = 0.07; gx1 = 0.77; gy0 = 0.08; gy1 = 0.88; gapx = 0.08; gapy = 0.12
  set logscale xy
  set grid
  set xlabel "CPU time of the solve [s]"
  set ylabel mlabel("sup_u")
  mode = 1; mc = mcol("sup_u")
  panel = 0
  do for [scene in forced_scenes] {
    panel = panel + 1
    row = 1 + (panel - 1) / 2; col = 1 + (panel - 1) % 2
    @panel_at
    set title sprintf("(%c) %s", 96 + panel, value('title_'.scene))
    @y_range
    @plot_curves
  }
  # (d) two exact runs from the chaotic start, v0 apart by 1e-10: their distance grows as
  # e^(lambda t); the horizon T of panel (b) is shorter than the Lyapunov time 1 / lambda.
  row = 2; col = 2
  @panel_at
  set title sprintf("(d) chaotic scene: two exact runs 10^{-10} apart in v_0,\n{/Symbol l} = %.2f /s, Lyapunov time 1/{/Symbol l} = %.2f s > T = %g s", lyapunov_lambda, 1 / lyapunov_lambda, lyapunov_T)
  set xlabel "t [s]"
  set ylabel "distance in the phase plane sqrt({/Symbol D}u^2 + {/Symbol D}v^2) [m, m/s]"
  unset logscale x
  set format x "%g"
  set logscale y
  set autoscale xy
  set ytics autofreq
  # key inside: the distance grows to the right, so the bottom right is empty, clear of the lines
  set key inside bottom right Left reverse font ",9" box opaque title ""
  set arrow 1 from lyapunov_T, graph 0 to lyapunov_T, graph 1 nohead dt 2 lc rgb "#D55E00"
  set arrow 2 from 1 / lyapunov_lambda, graph 0 to 1 / lyapunov_lambda, graph 1 nohead dt 3 lc rgb "#000000"
  plot results.'/lyapunov.csv' skip 1 using 1:($2 > 0 ? $2 : NaN) with lines lw 1 lc rgb "#999999" title "distance", \
       '' skip 1 using 1:3 with lines lw 2 lc rgb "#0072B2" title "running maximum", \
       '' skip 1 every ::0::0 using 1:3 with lines lc rgb "#D55E00" dt 2 title "horizon T of the study", \
       '' skip 1 every ::0::0 using 1:3 with lines lc rgb "#000000" dt 3 title "Lyapunov time 1/{/Symbol l}"
  unset arrow 1
  unset arrow 2
  unset key
  set format x "10^{%L}"
  key_curves = ""
  do for [scene in forced_scenes] {
    do for [c in value('curves_'.scene)] {
      if (strstrt(" ".key_curves." ", " ".c." ") == 0) { key_curves = key_curves." ".c }
    }
  }
  key_title = tolerance_note(key_curves)
  @key_strip
  unset multiplot
  }

  # --- direct_located against direct, moreau_jean and exact's cost (the vertical line) ---
  if (format eq "png") {
    set terminal pngcairo size 1300,1000 font ",10"
    set output out.'/work_precision_located.png'
  } else {
    set terminal svg size 1300,1000 font ",10" dynamic
    set output out.'/work_precision_located.svg'
  }
  set lmargin; set rmargin; set tmargin; set bmargin
  set border; set tics; unset title
  set multiplot layout 2,2 title "Work against precision of direct\\_located (each impact located inside its step): sup-norm error of u against CPU time\n(vertical line: exact sampled on h = 10^{-3} s; ".zero_note.")"
  set logscale xy
  set grid
  set xlabel "CPU time of the solve [s]"
  set ylabel mlabel("sup_u")
  set bmargin 6
  mode = 1; mc = mcol("sup_u")
  located_scenes = "figure3_no_cor figure3_cor075 figure4_cor075 table_period1"
  panel = 0
  do for [scene in located_scenes] {
    panel = panel + 1
    set title sprintf("(%c) %s", 96 + panel, value('title_'.scene))
    @y_range
    set key below horizontal nobox Left reverse font ",9" title " "
    if (exists('exact_seconds_'.scene)) { set arrow 1 from value('exact_seconds_'.scene), graph 0 to value('exact_seconds_'.scene), graph 1 nohead dt 2 lw 2 lc rgb "#000000" }
    plot for [c in "direct_located direct moreau_jean"] file(scene, c) skip 1 using 3:(yvalue(c, column(mc))) \
           with linespoints lc rgb col(c) dt dash(c) pt point(c) ps psize(c) lw 1.5 title tit(c)
    unset arrow 1
  }
  unset multiplot
  unset key
  set bmargin

  # --- one figure per scene: every measure against CPU time, against h, against the tolerance ---
  do for [scene in scenes] {
    has_penalty = strstrt(value('curves_'.scene), "penalty") > 0 || \
                  strstrt(value('curves_'.scene), "siconos_lsodar") > 0 || \
                  strstrt(value('curves_'.scene), "event_driven") > 0
    nrow = has_penalty ? 3 : 2; ncol = 4
    # Sixteen panels and a key on one page: a font that stays legible when the page is shown at a
    # README's width (it was 10 on 2000 pixels).
    if (format eq "png") {
      set terminal pngcairo size 2000, (has_penalty ? 1400 : 1000) font ",13"
      set output out.'/work_precision_'.scene.'.png'
    } else {
      set terminal svg size 2000, (has_penalty ? 1400 : 1000) font ",13" dynamic
      set output out.'/work_precision_'.scene.'.svg'
    }
    horizon = strstrt(value('title_'.scene), "T = ") ? "" : " (T = 10 s)"
    set multiplot title "Work against precision, ".value('title_'.scene).horizon."\n".zero_note
    gx0 = 0.06; gx1 = 0.77; gy0 = has_penalty ? 0.06 : 0.09; gy1 = has_penalty ? 0.89 : 0.85
    gapx = 0.065; gapy = has_penalty ? 0.1 : 0.14; key_font = ",13"
    set logscale xy
    set grid
    panel = 0
    do for [mode = 1:nrow] {
      set xlabel mode == 1 ? "CPU time of the solve [s]" : mode == 2 ? "step h [s]" : \
          "tolerance rtol = atol [1]"
      # The tolerances span 8 decades: a label every second one.
      if (mode == 3) { set xtics 100 } else { set xtics autofreq }
      against = mode == 1 ? "CPU time" : mode == 2 ? "the step h" : "the tolerance"
      row = mode
      do for [m in measures] {
        panel = panel + 1
        col = 1 + (panel - 1) % 4
        @panel_at
        mc = mcol(m)
        set title sprintf("(%c) %s against %s", 96 + panel, mtitle(m), against)
        set ylabel mlabel(m)
        @y_range
        @plot_curves
      }
    }
    key_curves = value('curves_'.scene)
    key_title = tolerance_note(key_curves)
    @key_strip
    unset multiplot
  }
}
