#include "known_scenes.h"

#include <array>

namespace crowdsim::crowds {

namespace {

constexpr const char* kEthCite =
    "S. Pellegrini, A. Ess, K. Schindler, L. van Gool, You'll never walk alone: modeling social "
    "behavior for multi-target tracking, ICCV 2009";
constexpr const char* kUcyCite =
    "A. Lerner, Y. Chrysanthou, D. Lischinski, Crowds by example, Computer Graphics Forum "
    "(Eurographics) 2007";

constexpr std::array<KnownScene, 6> kScenes{{
    {"biwi_eth.txt", "eth",
     "biwi_eth.txt, ETH (university entrance), BIWI Walking Pedestrians, ETH Zurich", kEthCite},
    {"biwi_hotel.txt", "hotel",
     "biwi_hotel.txt, Hotel (sidewalk), BIWI Walking Pedestrians, ETH Zurich", kEthCite},
    {"students001.txt", "univ1",
     "students001.txt, Univ (campus square, part 1), UCY Crowds by Example", kUcyCite},
    {"students003.txt", "univ3",
     "students003.txt, Univ (campus square, part 3), UCY Crowds by Example", kUcyCite},
    {"crowds_zara01.txt", "zara1",
     "crowds_zara01.txt, Zara 1 (shopping street), UCY Crowds by Example", kUcyCite},
    {"crowds_zara02.txt", "zara2",
     "crowds_zara02.txt, Zara 2 (shopping street), UCY Crowds by Example", kUcyCite},
}};

}  // namespace

std::span<const KnownScene> KnownScenes() { return kScenes; }

const KnownScene* FindKnownScene(const std::string& file_name) {
  for (const KnownScene& s : kScenes) {
    if (file_name == s.file) return &s;
  }
  return nullptr;
}

}  // namespace crowdsim::crowds
