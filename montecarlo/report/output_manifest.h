#pragma once
/// The manifest `.insmc-set` that insmc writes last into every output
/// folder: which command wrote the set and its file names. It tells the
/// next run whether the folder holds nothing but a previous set of the same
/// kind (then the whole folder may be swapped for the new set, see
/// montecarlo/report/output_set.h) and tells readers that the set is whole.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace insmc::mc {

inline constexpr std::string_view kManifestName = ".insmc-set";

struct OutputManifest {
  std::string command;              ///< e.g. "run", "covariance"
  std::vector<std::string> files;   ///< sorted file names of the set
};

/// "insmc output set 1\ncommand NAME\nfile NAME\n..." with the names sorted.
std::string render_manifest(const OutputManifest& manifest);

/// nullopt for anything that is not exactly a manifest render_manifest()
/// writes (then the folder is treated as holding foreign files).
std::optional<OutputManifest> parse_manifest(std::string_view text);

}  // namespace insmc::mc
