// lutbake's public API, in one header: every command of the `lutbake`
// executable is one call here (the executable only parses options into these
// requests and prints the results).
//
//   Bake                  tables, a bake plan or an engine preset into a directory (api/bake.h)
//   Plan                  what glTF scenes and manifests need (api/plan.h)
//   Evaluate              any table at any points, with each value's bound (api/eval.h)
//   Check                 a baked directory against the quadrature, identities and the
//                         furnace, or a preset's against its integrals (api/check.h)
//   Report                error against run time of every estimator, into a directory (api/report.h)
//   Furnace               the white furnace of a classic reflection model (api/furnace.h)
//   CheckPresetDirectory  a preset bake's files against the integrals (api/presets.h)
//   TableNames, FormatNames, PresetNames, ...: the accepted names (api/names.h)
//
// Errors are lutbake::Error (core/error.h): UsageError (the request cannot be
// done as asked), IoError and InputError (the work failed), Cancelled.
#pragma once

#include "lutbake/api/bake.h"
#include "lutbake/api/check.h"
#include "lutbake/api/eval.h"
#include "lutbake/api/furnace.h"
#include "lutbake/api/identify.h"
#include "lutbake/api/names.h"
#include "lutbake/api/plan.h"
#include "lutbake/api/presets.h"
#include "lutbake/api/report.h"
#include "lutbake/api/sampling.h"
#include "lutbake/core/cancellation.h"
#include "lutbake/core/error.h"
