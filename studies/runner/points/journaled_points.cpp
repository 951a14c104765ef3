#include "studies/runner/points/journaled_points.hpp"
#include "studies/runner/output/console.hpp"

#include <stdexcept>
#include <string_view>

#include "core/grid/point_pool.hpp"
#include "studies/runner/distributed/point_farm.hpp"
#include "studies/runner/output/progress_line.hpp"
#include "studies/runner/output/summary_file.hpp"

namespace orni::studies {

JournaledPointsJob journaledPointsJob(const std::string& kind,
                                      const std::filesystem::path& journal_path,
                                      const std::string& resolved_toml, std::size_t points,
                                      std::size_t columns) {
  JournaledPointsJob job;
  job.kind = kind;
  job.journal_path = journal_path;
  job.fingerprint = fnv1a64(versionString() + "\n" + resolved_toml);
  job.points = points;
  job.columns = columns;
  return job;
}

std::optional<JournaledPoints> runJournaledPoints(const JournaledPointsJob& job) {
  if (!farmWriter()) {  // a worker rank: compute the points rank 0 hands out, write nothing
    FarmJob farm;
    farm.threads = job.threads;
    farm.work = [&](std::size_t i, const std::string&) { return encodeSweepPoint(job.compute(i)); };
    runFarm(farm);
    return std::nullopt;
  }
  std::filesystem::create_directories(job.journal_path.parent_path());
  PointJournalResume resume;
  JournaledPoints out;
  out.journal = std::make_unique<PointJournal>(
      job.journal_path, job.kind, job.fingerprint, job.points,
      [&](std::size_t, std::string_view payload) {
        SweepPointResult r;
        return decodeSweepPoint(payload, job.columns, &r);
      },
      &resume);
  PointJournal& journal = *out.journal;
  noteJournalResume(job.kind, journal.path(), resume.existed, resume.fingerprint_matched,
                    std::to_string(resume.records) + " of " + std::to_string(job.points) +
                        " points already done",
                    resume.rejected_lines);

  out.rows.resize(job.points);
  out.resumed = resume.records;
  std::vector<std::size_t> todo;
  for (std::size_t i = 0; i < job.points; ++i) {
    if (resume.payloads[i])
      decodeSweepPoint(*resume.payloads[i], job.columns, &out.rows[i]);
    else
      todo.push_back(i);
  }
  out.computed = todo.size();

  std::optional<ProgressLine> progress;
  if (job.progress) progress.emplace(job.kind, job.points, resume.records);
  std::vector<SweepPointResult>& rows = out.rows;
  if (farmDistributed()) {
    // Rank 0 of a distributed run: the workers return each point as its journal payload, read
    // back as a resumed run reads it.
    FarmJob farm;
    farm.todo = todo;
    farm.threads = job.threads;
    farm.on_result = [&](std::size_t i, std::string payload) {
      if (!decodeSweepPoint(payload, job.columns, &rows[i]))
        throw std::runtime_error(job.kind + ": point " + std::to_string(i) +
                                 ": a worker rank returned an invalid result");
      journal.append(i, payload);
      if (progress) progress->pointDone();
      if (job.on_point) job.on_point(i, rows[i]);
    };
    runFarm(farm);
  } else {
    runPoints(
        todo, job.threads, [&](std::size_t i) { rows[i] = job.compute(i); },
        [&](std::size_t i) {
          journal.append(i, encodeSweepPoint(rows[i]));
          if (progress) progress->pointDone();
          if (job.on_point) job.on_point(i, rows[i]);
        });
  }
  if (progress) progress->finish();
  return out;
}

}  // namespace orni::studies
