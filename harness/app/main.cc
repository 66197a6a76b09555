// crowdsim-bench: the command-line entry point.
#include <algorithm>
#include <cctype>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "crowds/crowds_command.h"
#include "crowdsim/cli/args.h"
#include "crowdsim/version.h"
#include "floorplan/floorplan_command.h"
#include "process_group.h"

namespace {

/// One subcommand: its name, its entry point and its usage text.
struct Command {
  const char* name;
  int (*run)(const std::vector<std::string>&);
  const char* usage;
};

const std::vector<Command>& Commands() {
  static const std::vector<Command> commands = {
      {"run", crowdsim::cli::RunCommand,
       R"(  crowdsim-bench run SUITE.yaml [--out DIR] [--jobs N] [--episodes N] [--fresh] [--quiet] [--record] [--shard K/N]
                 [--set KEY.PATH=VALUE]...
      runs a suite; writes DIR/table.md, table.csv, episodes.csv, manifest.json
      (DIR defaults to runs/<suite name>/; the committed reference outputs under results/ are
      written only with an explicit --out); rerunning resumes finished episodes;
      --shard K/N runs only the K-th of N disjoint slices of the episodes (a cluster job array);
      --quiet leaves out the progress line and the resume notes on stderr (errors, warnings and
      the table still print);
      --set changes one key of the suite (humans.count=10, rows[orca].params.safety_space=0.1,
      robot.sensors[lidar2d].beams=90; recorded in manifest.json), as validate, render, train;
      --set isolation=on|off|auto runs episodes in worker processes (auto: when a plugin is
      not the harness's own or episode_timeout_s is set), so a crash or a hang past
      episode_timeout_s costs one episode (policy_crash / policy_timeout), not the run;
      --record writes every episode run as an episode log under DIR/logs/ (docs/episode_log.md)
)"},
      {"merge", crowdsim::cli::MergeCommand,
       R"(  crowdsim-bench merge SHARD_DIR... --out DIR [--suite SUITE.yaml] [--allow-mixed-commits]
      joins the output folders of `run --shard K/N` into the tables of a single run, after
      checking that they are one configuration and hold every episode exactly once, made by
      one commit (git_commit of their manifest.json); --allow-mixed-commits joins shards of
      different commits anyway (manifest.json records each shard's commit)
)"},
      {"validate", crowdsim::cli::ValidateCommand,
       R"(  crowdsim-bench validate FILE.yaml... [--set KEY.PATH=VALUE]...
      checks suites (and training files) without running them; reports every error with
      file:line:col, then builds every row as `run` does (weights and world files read, the
      sensors its policy needs, the scenario of the first episode of each frozen layout made
      and checked) and, for a row of the harness's own plugins, plays the first step of its
      episode 0, each error naming the row; a training file's learner, teacher and world are
      built as `train` builds them and play their first step
)"},
      {"train", crowdsim::cli::TrainCommand,
       R"(  crowdsim-bench train TRAIN.yaml [--resume] [--out DIR] [--seed N] [--quiet] [--set KEY.PATH=VALUE]...
      trains a learned policy (cadrl, sarl): imitation of a teacher (training.il_policy,
      ORCA by default), then RL; writes DIR/weights.pt, best.pt, il.pt, training_log.csv
      (validation), training_episodes.csv (every episode), learning_curve.svg/.png,
      summary.json (DIR defaults to results/train/<name>/, with --seed N to
      results/train/<name>_seed<N>/); checkpoints every 500 episodes and on Ctrl-C; --resume
      continues exactly, and goes on to a larger training.rl_episodes (e.g. --set
      training.rl_episodes=10000)
)"},
      {"train-all", crowdsim::cli::TrainAllCommand,
       R"(  crowdsim-bench train-all TRAIN.yaml[@SEED]... [--quiet] [--set KEY.PATH=VALUE]...
      a training campaign: each file (FILE@N: with seed N) as `train` runs it, resuming one
      with a checkpoint and skipping one finished with the same configuration; started by
      mpirun or srun, rank r of R takes files r, r+R, ... (one training per rank); alone, it
      trains them one after another (scripts/train_all.sh -j N runs N at a time on one machine)
)"},
      // Tools registered as commands (tools/floorplan, tools/crowds): entry points and usages
      // are their own.
      {"floorplan", crowdsim::floorplan::FloorplanCommand, crowdsim::floorplan::kFloorplanUsage},
      {"crowds", crowdsim::crowds::CrowdsCommand, crowdsim::crowds::kCrowdsUsage},
      {"render", crowdsim::cli::RenderCommand,
       R"(  crowdsim-bench render SUITE.yaml --row R --episode K [--compare R2] [--sensors-at STEP]
                 [--animate] [--speed X] [--scale S] [--set KEY.PATH=VALUE]... --out FILE.{svg,png,pdf,gif,mp4}
      draws one episode (rows 1.. as in the table or by label, episodes 0..): trajectories,
      time marks, outcome; --compare adds a second row's robot; --sensors-at draws the lidar
      and person readings at a step; --animate writes a .gif (or .mp4) at --speed x real time
)"},
      {"report", crowdsim::cli::ReportCommand,
       R"(  crowdsim-bench report RESULTS_DIR --out report.html [--suite SUITE.yaml]
      one self-contained HTML page of a run: table, charts, first success/collision/timeout;
      of a training folder (train --out): learning curve, validations, memory composition
      (--out FILE.svg/.png/.pdf: the learning curve alone)
)"},
      {"score", crowdsim::cli::ScoreCommand,
       R"(  crowdsim-bench score LOG_OR_FOLDER... [--out FILE.csv]
      the social navigation metrics (docs/metrics.md) of episode logs (docs/episode_log.md:
      `run --record` writes them under DIR/logs/, or convert another simulator's episodes):
      one CSV line per log, the columns as episodes.csv names them; a folder is searched for
      *.jsonl.gz and *.jsonl; a damaged or cut-short log is named and not scored (exit 1)
)"},
      {"list-plugins", crowdsim::cli::ListPluginsCommand,
       R"(  crowdsim-bench list-plugins [PLUGIN.so...]
      lists every plugin found, with its kind, description and parameters, and under
      `hides:` the files of its name in later folders (CROWDSIM_PLUGIN_PATH's come first)
)"},
  };
  return commands;
}

constexpr const char* kHeader =
    "crowdsim-bench: robot navigation among people and obstacles (CrowdSim++ in C++)\n\nusage:\n";

constexpr const char* kFooter = R"(  crowdsim-bench help [COMMAND]   (or COMMAND --help)
      this text, or one command's
  crowdsim-bench --version
      version, the git commit of the build, and whether it runs suites over MPI ranks
  crowdsim-bench completion bash
      a bash completion script: source <(crowdsim-bench completion bash)

)";

// Printed after the usage of every command and of one (help COMMAND, COMMAND --help).
constexpr const char* kNotes =
    R"(exit codes: 0 done; 1 failed while running (a plugin, a file, the disk); 2 usage or
validation error, or results that do not fit (another configuration or shard in --out, shards
that are not one run, no training or another one to --resume, a training's folder for a run or
a run's for a training, a folder another crowdsim-bench is writing into): nothing was run; 130
interrupted (train: checkpoint written, --resume).
environment: CROWDSIM_PLUGIN_PATH (extra plugin folders, searched first, ':'-separated),
CROWDSIM_DATA_DIR (where worlds/ is found; default: PREFIX/share/crowdsim-bench for an
installed copy, the source folder for a build).
)";

void PrintUsage(std::ostream& os) {
  os << kHeader;
  for (const Command& c : Commands()) os << c.usage;
  os << kFooter << kNotes;
}

const Command* Find(const std::string& name) {
  for (const Command& c : Commands()) {
    if (name == c.name) return &c;
  }
  return nullptr;
}

std::string Names() {
  std::string names;
  for (const Command& c : Commands()) names += std::string(c.name) + ", ";
  return names + "help, completion";
}

/// The synopsis lines of a usage text: "  crowdsim-bench NAME ..." and their continuations
/// ("                 [--set ...]"), not the description under them (which may name another
/// command's options, as merge's names run's --shard).
std::vector<std::string> SynopsisLines(const std::string& usage) {
  std::vector<std::string> lines;
  std::istringstream in(usage);
  for (std::string line; std::getline(in, line);) {
    const std::size_t text = line.find_first_not_of(' ');
    if (text == std::string::npos) continue;
    if (line.compare(text, 15, "crowdsim-bench ") == 0 || (text >= 10 && line[text] == '[')) {
      lines.push_back(line);
    }
  }
  return lines;
}

/// Completes the command names, then options and files (the options are read off the usage).
void PrintBashCompletion() {
  std::cout << "# bash completion for crowdsim-bench (source <(crowdsim-bench completion bash))\n"
               "_crowdsim_bench() {\n"
               "  local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
               "  if [[ $COMP_CWORD -eq 1 ]]; then\n"
               "    COMPREPLY=($(compgen -W \"";
  for (const Command& c : Commands()) std::cout << c.name << " ";
  std::cout << "help completion --version\" -- \"$cur\")); return\n  fi\n"
               "  case ${COMP_WORDS[1]} in\n";
  std::string names;
  for (const Command& c : Commands()) names += std::string(c.name) + " ";
  std::cout << "    help) [[ $COMP_CWORD -eq 2 ]] && COMPREPLY=($(compgen -W \"" << names
            << "completion\" -- \"$cur\"));;\n"
            << "    completion) [[ $COMP_CWORD -eq 2 ]] && COMPREPLY=($(compgen -W \"bash\" -- "
               "\"$cur\"));;\n";
  for (const Command& c : Commands()) {
    std::string opts, subcommands, with_value;
    for (const std::string& u : SynopsisLines(c.usage)) {
      for (std::size_t p = u.find("--"); p != std::string::npos; p = u.find("--", p + 2)) {
        std::size_t e = p + 2;
        while (e < u.size() && (std::isalnum(static_cast<unsigned char>(u[e])) || u[e] == '-')) ++e;
        const std::string opt = u.substr(p, e - p);
        if (opt.size() <= 2 || opts.find(opt + " ") != std::string::npos) continue;
        opts += opt + " ";
        // "--out DIR", "--kind navmesh|outline": a value follows (a flag ends at its ']').
        if (e + 1 < u.size() && u[e] == ' ' && u[e + 1] != '[' && u[e + 1] != '-') {
          with_value += (with_value.empty() ? "" : "|") + opt;
        }
      }
      // A lower-case word after the command's name is a subcommand (floorplan import).
      const std::string head = "crowdsim-bench " + std::string(c.name) + " ";
      if (const std::size_t at = u.find(head); at != std::string::npos) {
        const std::size_t from = at + head.size();
        const std::string word = u.substr(from, u.find(' ', from) - from);
        if (!word.empty() && std::islower(static_cast<unsigned char>(word[0])) &&
            subcommands.find(word + " ") == std::string::npos) {
          subcommands += word + " ";
        }
      }
    }
    std::cout << "    " << c.name << ") ";
    if (!with_value.empty()) {  // an option's value: files (or what the user types), no options
      std::cout << "case $prev in " << with_value
                << ") COMPREPLY=($(compgen -f -- \"$cur\")); return;; esac; ";
    }
    if (!subcommands.empty()) {
      std::cout << "if [[ $COMP_CWORD -eq 2 ]]; then COMPREPLY=($(compgen -W \"" << subcommands
                << "--help\" -- \"$cur\")); return; fi; ";
    }
    std::cout << "COMPREPLY=($(compgen -W \"" << opts << "--help\" -- \"$cur\") "
              << "$(compgen -f -- \"$cur\"));;\n";
  }
  std::cout << "  esac\n}\ncomplete -o filenames -F _crowdsim_bench crowdsim-bench\n";
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    PrintUsage(std::cerr);
    return 2;
  }
  if (args[0] == "--version" || args[0] == "version") {
    std::cout << "crowdsim-bench " << crowdsim::Version() << " (commit " << crowdsim::GitCommit()
              << ")" << (crowdsim::cli::BuiltWithMpi() ? ", with MPI" : "") << "\n";
    return 0;
  }
  if (args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    if (args.size() > 1 && (args[1] == "help" || args[1] == "completion" ||
                            args[1] == "--version" || args[1] == "version")) {
      std::cout << "usage:\n" << kFooter << kNotes;  // where help, --version, completion are
      return 0;
    }
    if (args.size() > 1) {
      const Command* c = Find(args[1]);
      if (c == nullptr) {
        std::cerr << "error: no command '" << args[1] << "' (valid: " << Names() << ")\n";
        return 2;
      }
      std::cout << "usage:\n" << c->usage << "\n" << kNotes;
      return 0;
    }
    PrintUsage(std::cout);
    return 0;
  }
  if (args[0] == "completion") {
    if (args.size() == 2 && (args[1] == "--help" || args[1] == "-h")) {
      std::cout << "usage:\n" << kFooter << kNotes;
      return 0;
    }
    if (args.size() != 2 || args[1] != "bash") {
      std::cerr << "error: completion needs the shell: crowdsim-bench completion bash\n";
      return 2;
    }
    PrintBashCompletion();
    return 0;
  }
  const Command* command = Find(args[0]);
  if (command == nullptr) {
    std::cerr << "error: unknown command '" << args[0] << "' (valid: " << Names() << ")\n"
              << "(run `crowdsim-bench help` for the usage of every command)\n";
    return 2;
  }
  args.erase(args.begin());
  // --help first; anywhere else among the options, Args::Parse says so (HelpRequested), as it
  // alone knows which tokens are option values (--out --help names a folder).
  if (!args.empty() && (args[0] == "--help" || args[0] == "-h")) {
    std::cout << "usage:\n" << command->usage << "\n" << kNotes;
    return 0;
  }
  try {
    return command->run(args);
  } catch (const crowdsim::cli::HelpRequested&) {
    std::cout << "usage:\n" << command->usage << "\n" << kNotes;
    return 0;
  } catch (const crowdsim::cli::UsageError& e) {
    std::cerr << "error: " << e.what() << "\nusage:\n" << command->usage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << "\n";
    return 1;
  }
}
