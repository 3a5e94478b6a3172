#include "cli/mpi_launch.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

#include "flexure/io/platform/mpi_world.h"
#include "flexure/io/platform/work_distribution.h"
#include "flexure/solver/common/status.h"

namespace flexure::cli {
namespace {

int saved_stdout = -1;

}  // namespace

void check_mpi_launch(int argc, char** argv) {
  const int ranks = parallel::launched_size();
  if (ranks <= 1) return;
  if (!parallel::mpi_build()) {
    throw InvalidInput(fmt::format(
        "this flexure was built without MPI (FLEXURE_MPI=OFF), and mpirun started {} copies: each "
        "would run the whole command. Build with -DFLEXURE_MPI=ON (docs/scaling.md) or run it "
        "without mpirun",
        ranks));
  }
  std::vector<std::string> words;  // the command words before the first flag
  bool all_subclasses = false, spring_rules = false, help = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--all-subclasses") all_subclasses = true;
    if (a == "--spring-rules" || a.rfind("--spring-rules=", 0) == 0) spring_rules = true;
    if (a == "--help" || a == "-h" || a == "--version") help = true;
    if (a.rfind("-", 0) != 0 && words.size() < 2 &&
        words.size() == static_cast<std::size_t>(i - 1)) {
      words.push_back(a);
    }
  }
  if (help || words.empty()) return;
  const std::string command = words.size() > 1 ? words[0] + " " + words[1] : words[0];
  const bool divides = command == "sweep beam" || command == "map cfm" ||
                       (command == "design cfm" && all_subclasses) ||
                       (command == "mechanism validate" && !spring_rules) ||
                       command == "mechanism tolerance";
  if (!divides) {
    throw InvalidInput(fmt::format(
        "'flexure {}{}' does not divide its work over MPI ranks, and mpirun started {} copies; run "
        "it without mpirun. Under mpirun: sweep beam, map cfm, design cfm --all-subclasses, "
        "mechanism validate without --spring-rules, mechanism tolerance (docs/scaling.md)",
        command,
        spring_rules && command == "mechanism validate" ? " --spring-rules" : "",
        ranks));
  }
}

void silence_stdout_of_other_ranks() {
  if (parallel::launched_size() <= 1 || parallel::launched_rank() == 0 || saved_stdout >= 0) return;
  std::cout.flush();
  std::fflush(stdout);
  saved_stdout = ::dup(STDOUT_FILENO);
  const int null = ::open("/dev/null", O_WRONLY);
  if (null >= 0) {
    ::dup2(null, STDOUT_FILENO);
    ::close(null);
  }
}

void report_balance() {
  const std::vector<long> counts = parallel::items_per_rank();
  if (counts.size() < 2) return;
  std::string text;
  for (long n : counts) text += (text.empty() ? "" : ", ") + std::to_string(n);
  std::cerr << fmt::format("flexure: {} ranks; items per rank: {}\n", counts.size(), text);
}

void restore_stdout() {
  if (saved_stdout < 0) return;
  std::cout.flush();
  std::fflush(stdout);
  ::dup2(saved_stdout, STDOUT_FILENO);
  ::close(saved_stdout);
  saved_stdout = -1;
}

}  // namespace flexure::cli
