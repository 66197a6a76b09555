// crowdsim-bench: the command-line entry point.
#include <iostream>
#include <string>
#include <vector>

#include "cli_args.h"
#include "commands.h"
#include "floorplan_cli.h"

namespace {

constexpr const char* kUsage = R"(crowdsim-bench: robot navigation among people and obstacles (CrowdSim++ in C++)

usage:
  crowdsim-bench run SUITE.yaml [--out DIR] [--jobs N] [--episodes N] [--fresh] [--quiet]
      runs a suite; writes DIR/table.md, table.csv, episodes.csv, manifest.json
      (DIR defaults to results/<suite name>/); rerunning resumes finished episodes
  crowdsim-bench validate FILE.yaml...
      checks suites (and training files) without running them; reports every error with
      file:line:col
  crowdsim-bench train TRAIN.yaml [--resume] [--out DIR] [--seed N] [--quiet]
      trains a learned policy (cadrl, sarl): imitation of ORCA, then RL; writes
      DIR/weights.pt, best.pt, il.pt, training_log.csv (validation), training_episodes.csv
      (every episode), learning_curve.svg/.png, summary.json (DIR defaults to
      results/train/<name>/, with --seed N to results/train/<name>_seed<N>/); checkpoints
      every 500 episodes and on Ctrl-C; --resume continues exactly
  crowdsim-bench floorplan import IMAGE [--resolution M] [--kind navmesh|outline] [--max-rectangles 30] --out WORLD.yaml
  crowdsim-bench floorplan preview WORLD.yaml [--image IMAGE] --out FILE.svg
  crowdsim-bench floorplan dataset --source DIR --out worlds/floorplans
      imports real floor plans into rectangle worlds (see worlds/floorplan/README.md)
  crowdsim-bench render SUITE.yaml --row R --episode K [--compare R2] [--sensors-at STEP]
                 [--animate] [--speed X] [--scale S] --out FILE.{svg,png,pdf,gif,mp4}
      draws one episode (rows 1.. as in the table or by label, episodes 0..): trajectories,
      time marks, outcome; --compare adds a second row's robot; --sensors-at draws the lidar
      and person readings at a step; --animate writes a .gif (or .mp4) at --speed x real time
  crowdsim-bench report RESULTS_DIR --out report.html [--suite SUITE.yaml]
      one self-contained HTML page of a run: table, charts, first success/collision/timeout;
      of a training folder (train --out): learning curve, validations, memory composition
      (--out FILE.svg/.png/.pdf: the learning curve alone)
  crowdsim-bench list-plugins [PLUGIN.so...]
      lists every plugin found, with its kind, description and parameters
  crowdsim-bench help
)";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::cout << kUsage;
    return args.empty() ? 2 : 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  try {
    if (command == "run") return crowdsim::cli::RunCommand(args);
    if (command == "validate") return crowdsim::cli::ValidateCommand(args);
    if (command == "list-plugins") return crowdsim::cli::ListPluginsCommand(args);
    if (command == "floorplan") return crowdsim::floorplan::RunFloorplanCli(args);
    if (command == "train") return crowdsim::cli::TrainCommand(args);
    if (command == "render") return crowdsim::cli::RenderCommand(args);
    if (command == "report") return crowdsim::cli::ReportCommand(args);
    std::cerr << "error: unknown command '" << command
              << "' (valid: run, validate, train, floorplan, render, report, list-plugins, help)\n\n" << kUsage;
    return 2;
  } catch (const crowdsim::cli::UsageError& e) {
    std::cerr << "error: " << e.what() << "\n(run `crowdsim-bench help` for the usage of every command)\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
