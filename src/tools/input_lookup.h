// Where a named input file is found: one rule for the scene (or model), the platform and the
// cost model, shared with the sweep tool (analysis/ncube/paths.py, find_input; the two are
// held together by tests/input_lookup_test.sh). docs/cli.md, "Finding the input files".
//
// A name is tried, in order:
//   1. as given: absolute, or relative to the current folder;
//   2. relative to the repository root (so that README examples such as
//      tests/models/cornell-box.obj or docs/examples/fat-tree-64.xml work from any folder);
//   3. a bare name (no '/') in the role's folders, as given and with each of the role's
//      extensions: scenes/ (.json) for a scene; platforms/ then platforms/machines/ (.json,
//      .xml) for a platform; platforms/ (.json) for a cost model.
// The first that exists is used; if none does, InputError lists every place tried.
#pragma once

#include <string>
#include <vector>

namespace ncube {

enum class InputRole { kScene, kPlatform, kCostModel };

// "scene", "platform", "cost model": the role as messages and --list-inputs name it.
const char* input_role_name(InputRole role);

// Every path `name` is looked for at, in order (the rule above), under repository `root`.
std::vector<std::string> input_candidates(const std::string& name, InputRole role,
                                          const std::string& root);

// The bare names (without extension) of the role's files in its folders under `root`, each
// once, folder by folder in the order tried, sorted within a folder.
std::vector<std::string> input_names(InputRole role, const std::string& root);

// The first candidate that exists (as the name was given when it exists as given, so that
// result files keep the paths the user wrote). A candidate whose existence cannot be told
// (a loop of links) counts as existing: the read gate reports it. Throws InputError:
//   "<name>: no such <role> file; did you mean <a> or <b>? (looked for: <candidate>, ...)"
// naming the role's files nearest to it ("; the nearest names in <folders>: ..." when none is
// close), the names shown by shown_text (control characters escaped, long ones cut).
std::string find_input(const std::string& name, InputRole role, const std::string& root);

}  // namespace ncube
