#pragma once
// The current time in UTC as text, for every file and report that records when it was written.
#include <string>

namespace rdsf {

/// The current UTC time formatted with strftime `format`; by default ISO 8601, "2026-11-22T05:30:00Z".
/// When SOURCE_DATE_EPOCH holds seconds since 1970, that time instead (reproducible files, e.g. the
/// shipped default model: scripts/train-default-model.sh).
std::string utc_now(const char* format = "%Y-%m-%dT%H:%M:%SZ");

/// utc_now() in ISO 8601, the form every sample set, model file and journal stores.
inline std::string utc_now_iso8601() { return utc_now(); }

}  // namespace rdsf
