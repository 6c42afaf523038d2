// Sweep specs (pipeline/SweepSpec.hpp) and the task graph made from them (SweepTasks.hpp).
#include <gtest/gtest.h>

#include <algorithm>

#include "TestTmp.hpp"
#include "slamroute/core/AtomicFile.hpp"
#include "slamroute/pipeline/SweepSpec.hpp"
#include "slamroute/pipeline/SweepTasks.hpp"

namespace slamroute::pipeline {
namespace {
namespace fs = std::filesystem;

const std::string kNets = std::string(SLAMROUTE_SOURCE_DIR) + "/networks/test/";

std::string specError(const fs::path& file, const std::string& yaml) {
  writeFileAtomic(file, yaml);
  try {
    SweepSpec::readYaml(file);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(SweepSpec, GridAndExplicitRows) {
  const auto dir = test::testTmp();
  writeFileAtomic(dir / "fast.yaml", "evaluate:\n  input:\n    scan_stride: 5\n");
  writeFileAtomic(dir / "s.yaml",
                  "nets: [" + kNets + "plus.net.xml, " + kNets +
                      "ring.net.xml]\nplanners: [qlearning, random]\nseeds: [1, 2]\n"
                      "variants:\n  - {name: fast, config: fast.yaml}\nrows:\n"
                      "  - {net: " +
                      kNets +
                      "plus.net.xml, planner: postman, seed: 7, variant: fast}\n"
                      "  - {net: " +
                      kNets + "plus.net.xml, planner: random, seed: 1, variant: fast}\n");
  const SweepSpec s = SweepSpec::readYaml(dir / "s.yaml");
  const auto rows = s.expand();
  ASSERT_EQ(rows.size(), 2u * 2u * 2u + 1u);  // the second explicit row is in the grid already
  EXPECT_EQ(rows[0], (SweepRow{kNets + "plus.net.xml", "qlearning", 1, "fast"}));
  EXPECT_EQ(rows.back(), (SweepRow{kNets + "plus.net.xml", "postman", 7, "fast"}));
  EXPECT_EQ(s.variant("fast").config_file, (dir / "fast.yaml").string());
}

TEST(SweepSpec, BadSpecsAreOneLineErrorsNamingTheFile) {
  const auto dir = test::testTmp();
  const fs::path f = dir / "bad.yaml";
  EXPECT_EQ(specError(f, "nets: [x.net.xml]\nplanners: [random]\nseeds: [1]\n"),
            f.string() + ": net 'x.net.xml' not found");
  EXPECT_EQ(specError(f, "planners: [random]\nseed: [1]\n"), f.string() + ": unknown key 'seed'");
  EXPECT_EQ(specError(f, "planners: [random]\n"),
            f.string() + ": no runs: give nets, planners and seeds, or rows");
  EXPECT_EQ(specError(f, "rows:\n  - {net: " + kNets +
                             "plus.net.xml, planner: random, seed: 1, variant: v}\n"),
            f.string() + ": unknown variant 'v'");
}

TEST(SweepTasks, OneSurveyAndGraphPerNetVariantAndSeedSharedByThePlanners) {
  SweepSpec s;
  s.nets = {kNets + "plus.net.xml"};
  s.planners = {"random", "qlearning"};
  s.seeds = {1, 2};
  s.variants = {SweepVariant{}};
  const auto tasks = sweepTasks(s, s.expand(), "/sweep", ChildOptions{});
  // Per seed: survey, graph, 2 plans, 2 drives, 2 evaluations.
  ASSERT_EQ(tasks.size(), 16u);
  auto find = [&](const std::string& name) {
    const auto it =
        std::find_if(tasks.begin(), tasks.end(), [&](const auto& t) { return t.name == name; });
    EXPECT_NE(it, tasks.end()) << name;
    return static_cast<std::size_t>(it - tasks.begin());
  };
  const std::size_t graph = find("plus/default/s2/build-graph");
  const std::size_t ql = find("plus/default/s2/plan qlearning");
  const std::size_t rnd = find("plus/default/s2/plan random");
  EXPECT_EQ(tasks[ql].deps, (std::vector<std::size_t>{graph}));
  // The random walk is budgeted by the same seed's Q-learning route, so it waits for it.
  EXPECT_EQ(tasks[rnd].deps, (std::vector<std::size_t>{graph, ql}));
  EXPECT_EQ(tasks[rnd].plan.budget_from, "qlearning");
  EXPECT_EQ(tasks[find("plus/default/s2/evaluate random")].deps,
            (std::vector<std::size_t>{find("plus/default/s2/drive random")}));
  EXPECT_EQ(tasks[ql].opts.seed, 2u);
  EXPECT_EQ(tasks[ql].run.out, fs::path("/sweep/plus/default/s2"));
  for (std::size_t i = 0; i < tasks.size(); ++i)
    for (std::size_t d : tasks[i].deps) EXPECT_LT(d, i);
}

}  // namespace
}  // namespace slamroute::pipeline
