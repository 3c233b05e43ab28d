// The bonding field's capture, escape and debond maps (beyond the paper). The recipe is
// run_bonding_field (src/analysis/bonding_field/bonding_field.hpp), which
// tests/test_bonding_field.cpp calls too.
#include "analysis/bonding_field/bonding_field.hpp"

int main(int argc, char** argv) {
  return impact::experiment_main(argc, argv, impact::bonding_field::kBondingFieldExperiment,
                                 IMPACT_SOURCE_DIR);
}
