#include "outputs/provenance.hpp"

#include <gtest/gtest.h>

#include "common/input_error.hpp"
#include "common/sha256.hpp"
#include "support/test_models.hpp"

namespace crux {
namespace {

TEST(Provenance, RecordsTheInputsDigestsAndTheSeed) {
  ExperimentConfig config;
  config.urdf = testing::write_temporary("provenance.urdf", testing::human_urdf_text()).string();
  config.wall_seed = 42;
  const Provenance p = record_provenance(config);
  EXPECT_EQ(p.urdf_sha256, sha256_hex(testing::human_urdf_text()));
  EXPECT_EQ(p.urdf, config.urdf) << "already absolute";
  EXPECT_EQ(p.wall_seed, 42u);
  EXPECT_TRUE(p.wall_sha256.empty());
  EXPECT_FALSE(p.crux_version.empty());
  const std::string toml = provenance_toml(p);
  EXPECT_NE(toml.find("[provenance]"), std::string::npos);
  EXPECT_NE(toml.find("urdf_sha256 = \"" + p.urdf_sha256 + "\""), std::string::npos);
  EXPECT_EQ(provenance_json(p)["wall_seed"], 42);
  EXPECT_TRUE(provenance_json(p)["wall_sha256"].is_null());
}

TEST(Provenance, AReplayWithAnotherFileIsRefusedNamingTheConfig) {
  ExperimentConfig config;
  config.urdf = testing::write_temporary("provenance_replay.urdf", testing::human_urdf_text()).string();
  const Provenance now = record_provenance(config);
  config.recorded_provenance["urdf_sha256"] = now.urdf_sha256;
  EXPECT_NO_THROW(check_recorded_provenance(config, now, "cfg.toml"));
  config.recorded_provenance["urdf_sha256"] = sha256_hex("another body");
  try {
    check_recorded_provenance(config, now, "cfg.toml");
    FAIL() << "accepted another URDF";
  } catch (const InputError& e) {
    EXPECT_EQ(e.source(), "cfg.toml");
    EXPECT_NE(e.problem().find("provenance.urdf_sha256"), std::string::npos) << e.what();
  }
  config.recorded_provenance.clear();
  config.recorded_provenance["q_grid_sha256"] = sha256_hex("a table");
  EXPECT_THROW(check_recorded_provenance(config, now, "cfg.toml"), InputError) << "the recorded Q_grid is missing";
}

}  // namespace
}  // namespace crux
