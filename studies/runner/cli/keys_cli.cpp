// `ornithopter keys [GROUP] [--markdown]`: the field table as text or Markdown; with --outputs the
// output table (studies/runner/output/output_schema.hpp).
#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/model/field_table.hpp"
#include "studies/runner/cli/cli_options.hpp"
#include "studies/runner/cli/subcommands.hpp"
#include "studies/runner/commands/keys_command.hpp"
#include "studies/runner/config/toml_access.hpp"
#include "studies/runner/output/output_schema.hpp"

namespace orni::studies::cli {

namespace {

struct KeysArgs {
  std::string group;
  bool markdown = false;
  bool outputs = false;
  std::vector<std::string> check_dirs;
};

std::string joined(const std::vector<std::string>& items) {
  std::string list;
  for (const std::string& g : items) list += (list.empty() ? "" : ", ") + g;
  return list;
}

/// `keys --outputs [KIND]`: the output table (output_schema.hpp), all of it or one run kind's.
int runOutputs(const KeysArgs& a) {
  if (!a.check_dirs.empty()) {  // --check DIR...: the run folders against the table
    int findings = 0;
    for (const std::string& dir : a.check_dirs) {
      OutputCheck c;
      try {
        c = checkRunFolder(dir);
      } catch (const std::runtime_error& e) {
        throw CliError(std::string("--check: ") + e.what());
      }
      for (const std::string& f : c.findings) std::cout << dir << ": " << f << "\n";
      findings += static_cast<int>(c.findings.size());
      std::cout << dir << ": " << c.kind << " run, " << c.summary_values << " summary values and "
                << c.csv_columns << " CSV columns, " << c.findings.size()
                << (c.findings.size() == 1 ? " finding" : " findings") << "\n";
    }
    return findings == 0 ? kExitOk : kExitFailed;
  }
  std::vector<std::string> kinds;
  for (std::string_view k : outputKinds()) kinds.emplace_back(k);
  if (!a.group.empty() && std::find(kinds.begin(), kinds.end(), a.group) == kinds.end()) {
    const std::string near = closestMatch(a.group, kinds);
    throw CliError("command line: KIND (with --outputs): expected one of " + joined(kinds) +
                   ", got '" + a.group + "'" +
                   (near.empty() ? std::string() : " (did you mean '" + near + "'?)"));
  }
  std::cout << outputListing(a.group, a.markdown);
  return kExitOk;
}

int runKeys(const KeysArgs& a) {
  if (a.outputs) return runOutputs(a);
  const std::optional<std::string> text = keysText(a.group, a.markdown);
  if (!text) {
    std::vector<std::string> groups;
    for (std::string_view g : fieldGroups()) groups.emplace_back(g);
    const std::string near = closestMatch(a.group, groups);
    throw CliError("command line: GROUP: expected one of " + joined(groups) + ", got '" + a.group +
                   "'" +
                   (near.empty() ? std::string() : " (did you mean '" + near + "'?)"));
  }
  std::cout << *text;
  return kExitOk;
}

}  // namespace

Subcommand addKeysSubcommand(CLI::App& app) {
  auto a = std::make_shared<KeysArgs>();
  auto* keys = app.add_subcommand(
      "keys",
      "Print every input key (vehicle files, study files, command line): unit, valid "
      "range, default and meaning, from the one table every reader checks");
  keys->add_option("GROUP", a->group,
                   "vehicle | study | simulate | aeromap | trim | optimize | calibrate | sweep | "
                   "sensitivity | continuation | cli (default: every group); with --outputs a "
                   "run kind: simulate | aeromap | trim | ... (default: every kind)");
  keys->add_flag("--markdown", a->markdown,
                 "Markdown tables (docs/keys.md, the key reference; with --outputs docs/outputs.md)");
  keys->add_flag("--outputs", a->outputs,
                 "List the outputs instead: every summary.json value and CSV column the runs "
                 "write, with unit and meaning");
  keys->add_option("--check", a->check_dirs,
                   "With --outputs: check finished run folders against the output table (every "
                   "summary value and CSV column described, CSV units as listed); exit 1 on a "
                   "finding")
      ->expected(1, -1);
  return {keys, [a] { return runKeys(*a); }, false};
}

}  // namespace orni::studies::cli
