// Atomic file output (architecture.md 4): write to a temporary file in the same folder, flush,
// then rename over the target, so an interrupted run never leaves a truncated file.
#pragma once

#include <filesystem>
#include <string>

namespace orni::studies {

/// "PID.N": a tag unique to this process and call (N counts up from 1, thread-safe), for the names
/// of temporary files and folders (PATH.tmp.PID.N), so that two writers never share one.
std::string uniqueTempTag();

/// Write `content` to `path` atomically (through PATH.tmp.PID.N); creates parent folders. Throws
/// std::runtime_error.
void writeFileAtomic(const std::filesystem::path& path, const std::string& content);

/// Shortest decimal text that reads back to exactly the same double (deterministic output).
std::string formatShortest(double value);

}  // namespace orni::studies
