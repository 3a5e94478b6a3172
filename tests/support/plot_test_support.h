#pragma once
// Helpers for the tests of the plot scripts (scripts/plot_*.py) under Debian's /usr/bin/python3:
// whether matplotlib and h5py are importable, running a script in a scratch directory, and the
// axis labels a script draws (read from the matplotlib figures themselves, not from the image).
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/cli_test_support.h"

namespace flexure::test {

inline const std::string kPython = "/usr/bin/python3";

inline bool python_has_plot_modules() {
  const std::string probe = kPython + " -c 'import matplotlib, h5py' >/dev/null 2>&1";
  return std::system(probe.c_str()) == 0;
}

// Runs `scripts/<script> <args>` in `dir` with stdout in out.txt and stderr in err.txt; returns
// the exit code. With `print_labels`, the script runs under a wrapper that prints the x and y
// label of every visible axes (colour bars included) of every figure it saves, one
// "AXIS-LABEL <label>" line each, before saving it.
inline int run_plot_script(const std::string& script,
                           const std::string& args,
                           const ScratchDir& dir,
                           bool print_labels = false) {
  std::string runner;
  if (print_labels) {
    std::ofstream(dir / "print_labels.py") << R"(import runpy
import sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.figure
save = matplotlib.figure.Figure.savefig
def savefig(self, *args, **kwargs):
    for ax in self.axes:
        if ax.axison:
            for label in (ax.get_xlabel(), ax.get_ylabel()):
                if label:
                    print("AXIS-LABEL", label)
    return save(self, *args, **kwargs)
matplotlib.figure.Figure.savefig = savefig
sys.argv = sys.argv[1:]
runpy.run_path(sys.argv[0], run_name="__main__")
)";
    runner = "print_labels.py ";
  }
  const std::string command = "cd '" + dir.path().string() + "' && " + kPython + " " + runner +
                              "'" + FLEXURE_SOURCE_DIR + "/scripts/" + script + "' " + args +
                              " >out.txt 2>err.txt";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// The labels printed by run_plot_script(..., true) in `output`.
inline std::vector<std::string> axis_labels(const std::string& output) {
  std::vector<std::string> labels;
  std::istringstream lines(output);
  const std::string prefix = "AXIS-LABEL ";
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(prefix, 0) == 0) labels.push_back(line.substr(prefix.size()));
  }
  return labels;
}

}  // namespace flexure::test
