// bench_collision (Google Benchmark): the vessel-disc collision test against a training world's
// 28 obstacles, (a) as CollisionChecker does it (bounding-circle cull, then direct FCL calls)
// and (b) through FCL's dynamic AABB-tree broad-phase manager, updated every step because the
// 17 vessels move. Decides which one CollisionChecker uses.
#include <benchmark/benchmark.h>
#include <fcl/broadphase/broadphase_dynamic_AABB_tree.h>
#include <fcl/broadphase/default_broadphase_callbacks.h>
#include <fcl/narrowphase/collision_object.h>

#include <CLI/CLI.hpp>

#include "env/collision_checker.h"
#include "env/fcl_shapes.h"
#include "env/training_scenario.h"
#include "env/vessel_model.h"
#include "src/cli.h"

namespace colav {
namespace {

struct World {
  Scenario scenario = TrainingScenarioGenerator().Make(3);
  std::vector<MovingObstacle> vessels;
  World() {
    for (const auto& spec : scenario.dynamic_obstacles) vessels.emplace_back(spec);
  }
};

void BM_CullThenDirectFcl(benchmark::State& state) {
  World world;
  CollisionChecker checker(CybershipModel::kRadius);
  checker.Load(world.scenario.static_obstacles, world.vessels);
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): benchmark idiom
    for (MovingObstacle& v : world.vessels) v.Advance(1.0);
    benchmark::DoNotOptimize(checker.Collides(world.scenario.vessel_position, world.vessels));
  }
}
BENCHMARK(BM_CullThenDirectFcl);

void BM_DynamicAabbTreeManager(benchmark::State& state) {
  World world;
  std::vector<std::unique_ptr<fcl::CollisionObjectd>> objects;
  fcl::DynamicAABBTreeCollisionManagerd manager;
  for (const CircleSpec& c : world.scenario.static_obstacles) {
    objects.push_back(std::make_unique<fcl::CollisionObjectd>(
        std::make_shared<fcl::Cylinderd>(c.radius, kPrismHeight), PlanarTransform(c.center)));
  }
  const std::size_t first_vessel = objects.size();
  for (const MovingObstacle& v : world.vessels) {
    objects.push_back(std::make_unique<fcl::CollisionObjectd>(
        FclPrism(v.hull()), PlanarTransform(v.hull().bound_center)));
  }
  for (auto& o : objects) manager.registerObject(o.get());
  manager.setup();
  fcl::CollisionObjectd disc(std::make_shared<fcl::Sphered>(CybershipModel::kRadius),
                             PlanarTransform(world.scenario.vessel_position));
  for (auto _ : state) {  // NOLINT(clang-analyzer-deadcode.DeadStores): benchmark idiom
    for (std::size_t k = 0; k < world.vessels.size(); ++k) {
      world.vessels[k].Advance(1.0);
      const Eigen::Vector2d& c = world.vessels[k].hull().bound_center;
      objects[first_vessel + k]->setTranslation(Eigen::Vector3d(c.x(), c.y(), 0.0));
      objects[first_vessel + k]->computeAABB();
    }
    manager.update();
    fcl::DefaultCollisionData<double> data;
    manager.collide(&disc, &data, fcl::DefaultCollisionFunction);
    benchmark::DoNotOptimize(data.result.isCollision());
  }
}
BENCHMARK(BM_DynamicAabbTreeManager);

}  // namespace
}  // namespace colav

// Google Benchmark's main, inside RunProgram and with ConfigFlags so that bench_collision answers
// --print-config (it has no configuration keys) like every program. Google Benchmark reads the
// other arguments, --help included.
int main(int argc, char** argv) {
  return colav::RunProgram("bench_collision", argc, argv, [](int argc, char** argv) {
    CLI::App app{"Compares FCL collision strategies (Google Benchmark)."};
    app.allow_extras();
    app.set_help_flag();
    const colav::ConfigFlags config_flags(app, colav::ConfigSchema());
    colav::ParseCommandLine(app, argc, argv);
    config_flags.Resolve();  // no keys: rejects any in --set or --config
    benchmark::Initialize(&argc, argv);
    if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;  // bad input, as everywhere
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
  });
}
