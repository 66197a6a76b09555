// Weights files: an identical round trip, and a clear error for weights of another model,
// sensor set or action count, and for a damaged file.
#include <gtest/gtest.h>

#include <fstream>

#include "temp_dir.h"
#include "value_rl/state_encoding.h"
#include "value_rl/value_network.h"
#include "value_rl/value_policy.h"

namespace crowdsim::value_rl {
namespace {

ValueRlConfig Config(Model model, SensorSet sensors, std::uint64_t seed = 0) {
  ValueRlConfig c;
  c.model = model;
  c.sensors = sensors;
  c.lidar_beams = 9;
  c.init_seed = seed;
  return c;
}

std::vector<EncodedState> SomeStates(const ValueRlConfig& c) {
  std::vector<EncodedState> states;
  for (int k = 0; k < 4; ++k) {
    EncodedState s;
    s.values = {3.0f + k, 1.0f, 0.0f, 0.3f, 0.2f * k, -0.1f};
    for (int b = 0; b < c.LidarInputs(); ++b) s.values.push_back(0.1f * ((b + k) % 10));
    if (UsesPerson(c.sensors)) {
      for (int h = 0; h <= k; ++h) {
        s.values.insert(s.values.end(), {1.0f + h, 0.5f * k, -0.3f, 0.2f, 0.3f, 1.5f + h, 0.6f});
      }
    }
    states.push_back(std::move(s));
  }
  return states;
}

std::vector<float> ValuesOf(ValuePolicy& p, const std::vector<EncodedState>& states) {
  std::vector<const EncodedState*> ptrs;
  for (const auto& s : states) ptrs.push_back(&s);
  return p.Values(ptrs);
}

// The networks apply their first layer to (state, row) pairs without building the joined
// rows; the result is the plain MLP's on the concatenation (so weights files keep their meaning).
TEST(WeightsFileTest, JoinedRowsEqualThePlainMlpOnTheConcatenation) {
  torch::manual_seed(3);
  auto mlp = Mlp(6 + 7, {20, 10, 1}, false);
  const torch::Tensor state = torch::randn({4, 6});
  const torch::Tensor rows = torch::randn({4, 3, 7});
  const torch::Tensor plain_first =
      mlp->forward(torch::cat({state.unsqueeze(1).expand({-1, 3, -1}), rows}, 2));
  EXPECT_TRUE(torch::allclose(ForwardJoined(mlp, state, rows, true), plain_first, 1e-5, 1e-6));
  const torch::Tensor plain_last =
      mlp->forward(torch::cat({rows, state.unsqueeze(1).expand({-1, 3, -1})}, 2));
  EXPECT_TRUE(torch::allclose(ForwardJoined(mlp, state, rows, false), plain_last, 1e-5, 1e-6));
}

TEST(WeightsFileTest, RoundTripIsIdentical) {
  testing::TempDir dir;
  for (Model model : {Model::kCadrl, Model::kSarl}) {
    for (SensorSet sensors : {SensorSet::kPerson, SensorSet::kLidar, SensorSet::kLidarPerson}) {
      const ValueRlConfig c = Config(model, sensors, 7);
      ValuePolicy saved(c);
      const auto file =
          dir.path() / (std::string(ModelName(model)) + "_" + SensorSetName(sensors) + ".pt");
      saved.SaveWeights(file);
      ValuePolicy other(Config(model, sensors, 8));
      const auto states = SomeStates(c);
      EXPECT_NE(ValuesOf(saved, states), ValuesOf(other, states));
      other.LoadWeights(file);
      EXPECT_EQ(ValuesOf(saved, states), ValuesOf(other, states)) << file;
    }
  }
}

TEST(WeightsFileTest, InitIsDeterministic) {
  const ValueRlConfig c = Config(Model::kSarl, SensorSet::kLidarPerson, 42);
  ValuePolicy a(c), b(c);
  EXPECT_EQ(ValuesOf(a, SomeStates(c)), ValuesOf(b, SomeStates(c)));
}

void ExpectRejected(const ValueRlConfig& loader, const std::filesystem::path& file,
                    const std::string& mismatch) {
  ValuePolicy p(loader);
  try {
    p.LoadWeights(file);
    ADD_FAILURE() << "accepted " << file << " for " << mismatch;
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(file.string()), std::string::npos) << msg;
    EXPECT_NE(msg.find(mismatch), std::string::npos) << msg;
  }
}

TEST(WeightsFileTest, MismatchesAreClearErrors) {
  testing::TempDir dir;
  const auto file = dir.path() / "cadrl_person.pt";
  ValuePolicy(Config(Model::kCadrl, SensorSet::kPerson)).SaveWeights(file);

  ExpectRejected(Config(Model::kSarl, SensorSet::kPerson), file,
                 "model: expected sarl, found cadrl");
  ExpectRejected(Config(Model::kCadrl, SensorSet::kLidarPerson), file,
                 "sensors: expected lidar+person, found person");
  ValueRlConfig with_stop = Config(Model::kCadrl, SensorSet::kPerson);
  with_stop.stop_action = true;
  ExpectRejected(with_stop, file, "actions: expected 17, found 16");

  const auto lidar_file = dir.path() / "cadrl_lidar.pt";
  ValuePolicy(Config(Model::kCadrl, SensorSet::kLidar)).SaveWeights(lidar_file);
  ValueRlConfig more_beams = Config(Model::kCadrl, SensorSet::kLidar);
  more_beams.lidar_beams = 45;
  ExpectRejected(more_beams, lidar_file, "lidar_beams: expected 45, found 9");

  // The route prior is part of what the weights mean; files without one have 0.
  ValueRlConfig routed = Config(Model::kSarl, SensorSet::kLidarPerson);
  routed.route = true;
  const auto plain_route = dir.path() / "sarl_route.pt";
  ValuePolicy(routed).SaveWeights(plain_route);
  ValueRlConfig with_prior = routed;
  with_prior.route_prior = 0.05;
  ExpectRejected(with_prior, plain_route, "route_prior: expected 0.05, found 0");
  const auto prior_file = dir.path() / "sarl_route_prior.pt";
  ValuePolicy(with_prior).SaveWeights(prior_file);
  ExpectRejected(routed, prior_file, "route_prior: expected 0, found 0.05");
  EXPECT_NO_THROW(ValuePolicy(with_prior).LoadWeights(prior_file));
  // So is its shape: the same weight, discounted, is another value.
  ValueRlConfig discounted = with_prior;
  discounted.route_prior_shape = RoutePriorShape::kDiscounted;
  ExpectRejected(discounted, prior_file, "route_prior: expected 0.05 discounted, found 0.05");
  const auto discounted_file = dir.path() / "sarl_route_discounted.pt";
  ValuePolicy(discounted).SaveWeights(discounted_file);
  ExpectRejected(with_prior, discounted_file, "route_prior: expected 0.05, found 0.05 discounted");
  EXPECT_NO_THROW(ValuePolicy(discounted).LoadWeights(discounted_file));

  // The action space: unicycle weights are refused as holonomic ones, and the other way round.
  ValueRlConfig unicycle = with_stop;
  unicycle.unicycle_actions = true;
  unicycle.rotation_samples = 8;
  const auto stop_file = dir.path() / "cadrl_stop.pt";
  ValuePolicy(with_stop).SaveWeights(stop_file);
  ExpectRejected(unicycle, stop_file, "action_space: expected unicycle, found holonomic");
  const auto unicycle_file = dir.path() / "cadrl_unicycle.pt";
  ValuePolicy(unicycle).SaveWeights(unicycle_file);
  ExpectRejected(with_stop, unicycle_file, "action_space: expected holonomic, found unicycle");
  EXPECT_NO_THROW(ValuePolicy(unicycle).LoadWeights(unicycle_file));

  ExpectRejected(Config(Model::kCadrl, SensorSet::kPerson), dir.path() / "missing.pt",
                 "does not exist");
  const auto junk = dir.Write("junk.pt", "not a torch archive");
  ExpectRejected(Config(Model::kCadrl, SensorSet::kPerson), junk, "not a libtorch archive");
}

// Flips one byte inside the data of the archive entry whose name ends with `suffix` (found
// through its local header: signature, 26 bytes of fields, name and extra lengths, name, extra)
// and returns the entry's name.
std::string FlipDataByte(const std::filesystem::path& file, const std::string& suffix) {
  std::string bytes = testing::ReadText(file);
  const std::string signature = "PK\x03\x04";
  for (std::size_t at = bytes.find(signature); at != std::string::npos;
       at = bytes.find(signature, at + 1)) {
    const auto u16 = [&](std::size_t p) {
      return static_cast<unsigned char>(bytes[p]) | static_cast<unsigned char>(bytes[p + 1]) << 8;
    };
    const std::string name = bytes.substr(at + 30, u16(at + 26));
    if (!name.ends_with(suffix)) continue;
    bytes[at + 30 + name.size() + u16(at + 28) + 5] ^= 0x10;
    std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
    return name;
  }
  ADD_FAILURE() << "no entry ending with " << suffix << " in " << file;
  return "";
}

TEST(WeightsFileTest, DamagedFilesAreClearErrors) {
  testing::TempDir dir;
  const ValueRlConfig c = Config(Model::kCadrl, SensorSet::kPerson);
  const auto flipped = dir.path() / "flipped.pt";
  ValuePolicy(c).SaveWeights(flipped);
  const std::string entry = FlipDataByte(flipped, "/data/0");
  ASSERT_FALSE(entry.empty());
  ExpectRejected(c, flipped, "is damaged: entry '" + entry + "': its CRC-32 is ");
  ExpectRejected(c, flipped, "train it again (`crowdsim-bench train`) or download it again");

  const auto truncated = dir.path() / "truncated.pt";
  ValuePolicy(c).SaveWeights(truncated);
  const std::string whole = testing::ReadText(truncated);
  std::ofstream(truncated, std::ios::binary | std::ios::trunc) << whole.substr(0, whole.size() / 2);
  ExpectRejected(c, truncated, "is damaged: the archive's end record is missing");
}

}  // namespace
}  // namespace crowdsim::value_rl
