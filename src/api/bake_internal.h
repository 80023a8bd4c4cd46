// What bake.cpp and preset_bake.cpp share (not public).
#pragma once

#include <string>
#include <vector>

#include "lutbake/api/bake.h"

namespace lutbake {

// The preset path of Bake (preset_bake.cpp).
BakeResult BakePreset(const BakeRequest &request);
// Throws UsageError for a name in request.tables that no table has.
void ValidateTableNames(const BakeRequest &request);

// Throws UsageError for an option the request sets that applies to none of
// its tables or files (bake_validation.cpp).
void ValidateApplicability(const BakeRequest &request);

// The models a request sets (BakeRequest, EvalRequest: optional ndf, smith,
// fresnel, sheenVisibility, sheenAlpha) over `settings`' defaults.
template <typename Request>
void ApplyModels(const Request &r, BakeSettings *settings) {
  settings->ndf = r.ndf.value_or(settings->ndf);
  settings->smith = r.smith.value_or(settings->smith);
  settings->fresnel = r.fresnel.value_or(settings->fresnel);
  settings->sheenVisibility = r.sheenVisibility.value_or(settings->sheenVisibility);
  settings->sheenAlpha = r.sheenAlpha.value_or(settings->sheenAlpha);
}

std::vector<std::string> DefaultFormats();  // exr, bin, header
// "a,b,c", as a list option spells it.
std::string JoinList(const std::vector<std::string> &items);
// A number as std::ostream prints it by default ("1e-06").
std::string StreamedNumber(double value);
double MeanSamples(const BakedTable &table);
// `requested` worker threads, or all cores when it is 0.
int ThreadCount(int requested);

}  // namespace lutbake
