// `kind = "calibrate"` studies (trim/calibration.hpp): summary.json, calibration.csv (every settled
// free flight), calibrated_vehicle.toml (the vehicle with the calibrated values, ready to run) and
// study.resolved.toml.
#pragma once

#include <filesystem>

#include "studies/runner/config/study_file.hpp"

namespace orni::studies {

/// Exit code 0 when the run finished (calibrated or not: the verdict is in summary.json).
int runCalibrateStudy(const Study& study, const std::filesystem::path& out_dir);

}  // namespace orni::studies
