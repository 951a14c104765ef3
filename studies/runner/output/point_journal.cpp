#include "studies/runner/output/point_journal.hpp"

#include <charconv>
#include <system_error>
#include <utility>

namespace orni::studies {

namespace {

std::string header(const std::string& label, std::uint64_t fingerprint, std::size_t points) {
  return "# ornithopter " + label + " journal v1 fingerprint=" + hex16(fingerprint) +
         " points=" + std::to_string(points);
}

}  // namespace

std::uint64_t fnv1a64(std::string_view text) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

std::string pointJournalRecord(std::size_t index, std::string_view payload) {
  std::string line = std::to_string(index);
  line += ',';
  for (const char c : payload) line += (c == '\n' || c == '\r') ? ' ' : c;
  return hex16(fnv1a64(line)) + ' ' + line + '\n';
}

bool parsePointJournalRecord(std::string_view line, std::size_t points, std::size_t* index,
                             std::string_view* payload) {
  if (line.size() < 18 || line[16] != ' ') return false;
  const std::string_view rest = line.substr(17);
  if (hex16(fnv1a64(rest)) != line.substr(0, 16)) return false;
  const std::size_t comma = rest.find(',');
  if (comma == std::string_view::npos || comma == 0) return false;
  std::size_t i = 0;
  const auto r = std::from_chars(rest.data(), rest.data() + comma, i);
  if (r.ec != std::errc() || r.ptr != rest.data() + comma || i >= points) return false;
  *index = i;
  *payload = rest.substr(comma + 1);
  return true;
}

PointJournal::PointJournal(std::filesystem::path file, std::string label, std::uint64_t fingerprint,
                           std::size_t points, const JournalPayloadCheck& accept,
                           PointJournalResume* resume) {
  PointJournalResume r;
  r.payloads.resize(points);
  auto keep = [&](std::string_view line) {
    std::size_t index = 0;
    std::string_view payload;
    if (!parsePointJournalRecord(line, points, &index, &payload) || r.payloads[index] ||
        (accept && !accept(index, payload)))
      return false;
    r.payloads[index] = std::string(payload);
    ++r.records;
    return true;
  };
  JournalFile::Reading reading;
  file_.emplace(std::move(file), header(label, fingerprint, points), keep, &reading);
  r.existed = reading.existed;
  r.fingerprint_matched = reading.header_matched;
  r.rejected_lines = reading.rejected_lines;
  if (resume) *resume = std::move(r);
}

void PointJournal::append(std::size_t index, std::string_view payload) {
  file_->append(pointJournalRecord(index, payload));
}

void PointJournal::remove() { file_->remove(); }

}  // namespace orni::studies
