// The library's public API in one include, for a program that uses the installed package
// (docs/library.md): the model, the steppers behind one interface and their table
// (capabilities.hpp, any_stepper.hpp), the time loop, one run of a scene as a value
// (run_result.hpp), the exact reference and the error norms, the ensemble, and the writers of rows
// and events.
#pragma once

#include "impact/chain/chain_moreau_jean.hpp"
#include "impact/chain/chain_reference.hpp"
#include "impact/ensemble/ensemble.hpp"
#include "impact/forces/internal.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/loop/stepper.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/model/model.hpp"
#include "impact/output/csv.hpp"
#include "impact/references/event_driven.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/error_norms.hpp"
#include "impact/run/run_result.hpp"
#include "impact/run/run_scene.hpp"
#include "impact/run/scene.hpp"
#include "impact/run/step_events.hpp"
#include "impact/run/summary.hpp"
#include "impact/steppers/direct.hpp"
#include "impact/steppers/direct_located.hpp"
#include "impact/steppers/fb_newton.hpp"
#include "impact/steppers/moreau_jean.hpp"
#include "impact/steppers/penalty.hpp"
#include "impact/steppers/with_internal.hpp"
#include "impact/version.hpp"
