#include "studies/runner/output/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <system_error>
#include <utility>

#include "studies/runner/output/run_outputs.hpp"

namespace orni::studies {

namespace {
constexpr std::size_t kWriteBuffer = 1 << 16;  // bytes buffered before a write(2)
}  // namespace

std::string uniqueTempTag() {
  static std::atomic<unsigned long> counter{0};
  return std::to_string(::getpid()) + "." + std::to_string(counter.fetch_add(1) + 1);
}

AtomicFileWriter::AtomicFileWriter(std::filesystem::path path) : path_(std::move(path)) {
  namespace fs = std::filesystem;
  claimRunFolder(path_);  // a run's first file: the earlier run's outputs go first
  if (path_.has_parent_path()) fs::create_directories(path_.parent_path());
  tmp_ = path_.string() + ".tmp." + uniqueTempTag();
  file_ = std::fopen(tmp_.c_str(), "wb");
  if (!file_) throw std::runtime_error("cannot open " + tmp_.string() + " for writing");
  std::setvbuf(file_, nullptr, _IOFBF, kWriteBuffer);
}

AtomicFileWriter::~AtomicFileWriter() { discard(); }

void AtomicFileWriter::discard() {
  if (!file_) return;
  std::fclose(file_);
  file_ = nullptr;
  std::remove(tmp_.c_str());
}

void AtomicFileWriter::write(std::string_view text) {
  if (!file_) throw std::logic_error("AtomicFileWriter: write after commit");
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size()) {
    discard();
    throw std::runtime_error("cannot write " + tmp_.string());
  }
}

void AtomicFileWriter::commit() {
  if (!file_) throw std::logic_error("AtomicFileWriter: commit twice");
  const bool ok = std::fflush(file_) == 0 && ::fsync(::fileno(file_)) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!closed || !ok) {
    std::remove(tmp_.c_str());
    throw std::runtime_error("cannot write " + tmp_.string());
  }
  std::error_code ec;
  std::filesystem::rename(tmp_, path_, ec);
  if (ec) {
    std::remove(tmp_.c_str());
    throw std::runtime_error("cannot rename " + tmp_.string() + " to " + path_.string() + ": " +
                             ec.message());
  }
}

void writeFileAtomic(const std::filesystem::path& path, const std::string& content) {
  AtomicFileWriter w(path);
  w.write(content);
  w.commit();
}

std::string formatCell(double value) {
  return std::isfinite(value) ? formatShortest(value) : std::string();
}

std::string formatFixed(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", digits, value);
  return buf;
}

std::string formatShortest(double value) {
  std::string s;
  appendShortest(&s, value);
  return s;
}

void appendShortest(std::string* out, double value) {
  if (std::isnan(value)) {
    out->append("nan");
  } else if (std::isinf(value)) {
    out->append(value > 0 ? "inf" : "-inf");
  } else if (value == 0.0) {
    out->push_back('0');  // also maps -0 to 0
  } else {
    char buf[64];
    const auto res = std::to_chars(buf, buf + sizeof buf, value);
    out->append(buf, res.ptr);
  }
}

}  // namespace orni::studies
