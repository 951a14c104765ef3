// Version text shared by --version and summary.json.
#pragma once

#include <string>

namespace orni::studies {

/// "0.1.0 (git abc1234)".
std::string versionString();

}  // namespace orni::studies
