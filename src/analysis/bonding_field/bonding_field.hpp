// The bonding field's capture and escape (beyond the paper: its announced future work,
// paper_notes/bonding_field.md): a particle launched from the floor at v0 with bonds of fraction
// beta0 (or of threshold eps_a), run by event_driven with the bonds' events (bond_events.hpp), and
// sorted by its fate. The derived boundary is marked apart from what is found: no bond breaks
// while gamma R^2 <= eps_a along the first flight, whose top is well_height(gamma beta0^2, G, 0,
// v0) (v0^2 <= eps_a beta0^2 for f = 0 and L past the top), and such a flight turns at half of
// well_return_time; where the particle escapes is found only.
#pragma once

#include <toml++/toml.h>

#include "analysis/experiment.hpp"

namespace impact::bonding_field {

// A point's fate, in the CSV's `fate` column and the figure's colours.
enum class Fate {
  intact = 0,     // it came back and no bond broke (beta_T = beta0)
  damaged = 1,    // it came back with fewer bonds, beta_T in (debond_below, beta0)
  debonded = 2,   // beta fell to bonding.debond_below without an escape
  escaped = 3,    // the escape event: it never comes back (f = 0)
  undecided = 4,  // none of these by T
};

// Returns {bonding_field = {<map> = {...}}} for the maps free_beta0 (f = 0, over (v0, beta0)),
// free_eps_a (f = 0, beta0 = 0.5, over (v0, eps_a)), gravity_beta0 (f = -9.81, over (v0, beta0))
// and table_beta0 (the glued ball at rest on the vibrating table, f = -g + Gamma g sin(omega t),
// over (Gamma, beta0)): the counts of each fate, how many points the derived no-damage region holds
// and how many disagree with it (beta changed inside, unchanged outside), the largest error of a
// capture time inside it against half the harmonic return time, and per row the smallest x that
// escapes (the launches) or debonds (the table), with the rows where that fate is not monotone in
// x. Writes <map>.csv: v0 or Gamma, the row's key, fate, capture_time, escape_time, debond_time,
// beta_T, no_damage (1 inside the derived region).
toml::table run_bonding_field(const ExperimentContext& context);

extern const Experiment kBondingFieldExperiment;

}  // namespace impact::bonding_field
