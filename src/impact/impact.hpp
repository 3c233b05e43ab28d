// The library's public API in one include, for a program that uses the installed package
// (docs/library.md): the model, the steppers behind one interface and their table
// (capabilities.hpp, any_stepper.hpp), the time loop, one run of a scene as a value
// (run_result.hpp), the exact reference and the error norms, the ensemble, and the writers of rows
// and events.
#pragma once

#include "impact/any_stepper.hpp"
#include "impact/capabilities.hpp"
#include "impact/chain_moreau_jean.hpp"
#include "impact/chain_reference.hpp"
#include "impact/contact_law.hpp"
#include "impact/direct.hpp"
#include "impact/direct_located.hpp"
#include "impact/ensemble.hpp"
#include "impact/error_norms.hpp"
#include "impact/event_driven.hpp"
#include "impact/exact.hpp"
#include "impact/fb_newton.hpp"
#include "impact/internal.hpp"
#include "impact/internal_stepper.hpp"
#include "impact/model.hpp"
#include "impact/moreau_jean.hpp"
#include "impact/output.hpp"
#include "impact/penalty.hpp"
#include "impact/run.hpp"
#include "impact/run_result.hpp"
#include "impact/run_scene.hpp"
#include "impact/scene.hpp"
#include "impact/step_events.hpp"
#include "impact/stepper.hpp"
#include "impact/summary.hpp"
#include "impact/version.hpp"
