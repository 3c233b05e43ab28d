// Which impact this is: the version of the package (CMake's project version, CHANGELOG.md) and the
// commit it was built from, for `impact --version` and for the provenance of what it writes.
#pragma once

#include <string_view>

namespace impact {

std::string_view version();
// The git commit's hash, with "-dirty" when the tree had changes, or "unknown" outside a
// checkout (cmake/version_file.cmake writes its definition at every build).
std::string_view commit();

}  // namespace impact
