# The bonding field (beyond the paper): the fate of a particle launched from the floor at v0, run by
# event_driven with the bonds' events. (a) f = 0 over (v0, beta0), (b) f = 0 over (v0, eps_a) with
# beta0 = 0.5, (c) f = -9.81, elastic, over (v0, beta0), (d) the glued ball at rest on the
# vibrating table, f = -g + Gamma g sin(10 t), over (Gamma, beta0). gamma = 100, L = 0.1, eps_a =
# 0.25 unless varied. The dashed lines are derived, not fitted: below them no bond breaks on the
# first flight (gamma R^2 <= eps_a at its top: v0^2 <= eps_a beta0^2 + 2 G sqrt(eps_a/gamma)),
# and left of Gamma = 1 the ball never leaves the table; where the particle escapes or the bond
# breaks is found only.
# Usage: gnuplot -e "results='results/bonding_field'" experiments/bonding_field/plot.gp
if (!exists("results")) results = 'results/bonding_field'
set datafile separator ','
colors = "#009E73 #E69F00 #CC79A7 #D55E00 #999999"
labels = "'came back, no bond broke' 'came back, bonds broke' 'debonded (beta fell to 0.01; in (d) to 0.1), no escape' 'escaped (never comes back)' 'undecided by T'"
G = 9.81
gamma = 100.0
eps_a = 0.25

do for [format in "png svg"] {
  if (format eq "png") {
    set terminal pngcairo size 1300,1100 font ",10"
    set output 'figures/bonding_field.png'
  } else {
    set terminal svg size 1300,1100 font ",10" dynamic
    set output 'figures/bonding_field.svg'
  }
  set multiplot layout 2,2 title \
      "The bonding field: the fate of a bonded particle (event\\_driven, gamma = 100, L = 0.1)"
  set grid
  set xlabel "v_0 [m/s]"
  set xrange [0:2.05]  # fixed range: from v0 = 0, where the derived lines start
  # Every key below its panel, in a bottom margin of the same height, so that the panels line up.
  set bmargin 9
  set key below horizontal maxcols 2 nobox
  set samples 400

  set title "(a) f = 0, eps_a = 0.25: over (v_0, beta_0)"
  set ylabel "beta_0 [1]"
  set yrange [0:1.05]  # fixed range: beta0 and eps_a span [0, 1], drawn whole
  plot for [k=0:4] results.'/free_beta0.csv' skip 1 using 1:($3 == k ? $2 : NaN) \
         with points pt 5 ps 0.9 lc rgb word(colors, k + 1) title word(labels, k + 1), \
       (x / sqrt(eps_a) <= 1 ? x / sqrt(eps_a) : NaN) with lines dt 2 lw 2 lc rgb "black" \
         title "derived: v_0 = beta_0 sqrt(eps_a), no damage below"

  set title "(b) f = 0, beta_0 = 0.5: over (v_0, eps_a)"
  set ylabel "eps_a [m^2/s^2]"
  set yrange [0:1.05]  # fixed range: beta0 and eps_a span [0, 1], drawn whole
  plot for [k=0:4] results.'/free_eps_a.csv' skip 1 using 1:($3 == k ? $2 : NaN) \
         with points pt 5 ps 0.9 lc rgb word(colors, k + 1) notitle, \
       (x * x / 0.25 <= 1 ? x * x / 0.25 : NaN) with lines dt 2 lw 2 lc rgb "black" \
         title "derived: eps_a = v_0^2 / beta_0^2, no damage above"

  set title "(c) f = -9.81, elastic, eps_a = 0.25: over (v_0, beta_0)"
  set ylabel "beta_0 [1]"
  set yrange [0:1.05]  # fixed range: beta0 and eps_a span [0, 1], drawn whole
  gstar = 2 * G * sqrt(eps_a / gamma)
  plot for [k=0:4] results.'/gravity_beta0.csv' skip 1 using 1:($3 == k ? $2 : NaN) \
         with points pt 5 ps 0.9 lc rgb word(colors, k + 1) notitle, \
       (x * x > gstar && (x * x - gstar) / eps_a <= 1 ? sqrt((x * x - gstar) / eps_a) : NaN) \
         with lines dt 2 lw 2 lc rgb "black" \
         title "derived: v_0^2 = eps_a beta_0^2 + 2 G sqrt(eps_a/gamma)"

  set title "(d) the glued ball on the vibrating table, omega = 10 rad/s, COR 0.5, T = 3 s"
  set xlabel "Gamma = a / g [1]"
  set ylabel "beta_0 [1]"
  set xrange [0:5.2]  # fixed range: from Gamma = 0, the table at rest
  set yrange [0:1.05]  # fixed range: beta0 spans [0, 1], drawn whole
  set parametric
  set trange [0:1.05]  # fixed range: the line Gamma = 1 over the whole beta0 axis
  plot for [k=0:4] results.'/table_beta0.csv' skip 1 using 1:($3 == k ? $2 : NaN) \
         with points pt 5 ps 0.9 lc rgb word(colors, k + 1) notitle, \
       1, t with lines dt 2 lw 2 lc rgb "black" \
         title "derived: Gamma = 1, the ball never leaves the table left of it"
  unset parametric
  unset multiplot
}
