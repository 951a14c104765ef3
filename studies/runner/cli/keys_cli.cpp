// `ornithopter keys [GROUP] [--markdown]`: the field table as text or Markdown.
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

namespace orni::studies::cli {

namespace {

struct KeysArgs {
  std::string group;
  bool markdown = false;
};

int runKeys(const KeysArgs& a) {
  const std::optional<std::string> text = keysText(a.group, a.markdown);
  if (!text) {
    std::vector<std::string> groups;
    for (std::string_view g : fieldGroups()) groups.emplace_back(g);
    const std::string near = closestMatch(a.group, groups);
    std::string list;
    for (const std::string& g : groups) list += (list.empty() ? "" : ", ") + g;
    throw CliError("command line: GROUP: expected one of " + list + ", got '" + a.group + "'" +
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
                   "sensitivity | continuation | cli (default: every group)");
  keys->add_flag("--markdown", a->markdown, "Markdown tables (docs/keys.md, the key reference)");
  return {keys, [a] { return runKeys(*a); }, false};
}

}  // namespace orni::studies::cli
