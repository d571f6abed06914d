#pragma once
// What built this crux: its version, and the git commit of the source tree when the
// build could ask git (with "-dirty" when the tree had uncommitted changes).

#include <string>

namespace crux {

const std::string& crux_version();
const std::string& git_commit();  // empty when unknown

}  // namespace crux
