// The six ETH/UCY scene files of ../shared/pedestrians: each one's scene name and the credit every
// derived file carries (the data's README asks for both).
#pragma once

#include <span>
#include <string>

namespace crowdsim::crowds {

struct KnownScene {
  const char* file;    ///< the scene file's name
  const char* scene;   ///< our name: worlds/crowds/<scene>.tracks
  const char* source;  ///< what was recorded, where
  const char* cite;    ///< the paper to cite
};

/// The six scenes, in the data README's order.
std::span<const KnownScene> KnownScenes();
/// The known scene of a file name, or null.
const KnownScene* FindKnownScene(const std::string& file_name);

}  // namespace crowdsim::crowds
