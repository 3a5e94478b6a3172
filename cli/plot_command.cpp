// `flexure plot FILE.h5 [--out FIG.png|.pdf|.svg] [--animate FILE.gif]`: draws any HDF5 file the
// tool writes. The drawing is the Python package flexure_plot (python/flexure_plot, matplotlib and
// h5py under Debian's /usr/bin/python3; docs/cli.md "flexure plot"); this command only finds the
// package (build tree or install), runs it and reports its answer, so that the figures are the
// same whether made by `flexure plot`, `python3 -m flexure_plot` or an example script.
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli/cli_common.h"
#include "cli/commands.h"

extern char** environ;

namespace flexure::cli {
namespace {

namespace fs = std::filesystem;

struct PlotArgs {
  std::string file;
  std::string out;
  std::string animate;
  std::string dump_json;
  bool json = false;
  bool no_stress = false;  // mechanism analyze files: no stress panel
  double n = 0.0;          // models map files: the plane's load ratio, when --n is given
  CLI::Option* n_option = nullptr;
};

// Folders that may hold the package flexure_plot, in the order searched: $FLEXURE_PLOT_PATH, the
// build tree (share/ next to the executable, where CMake copies it), the install
// (<prefix>/bin/flexure -> <prefix>/share/flexure/python) and the configured install prefix.
std::vector<fs::path> plot_module_candidates() {
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("FLEXURE_PLOT_PATH"); env != nullptr && *env != '\0') {
    dirs.emplace_back(env);
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    dirs.push_back(exe.parent_path() / "share" / "flexure" / "python");
    dirs.push_back(exe.parent_path().parent_path() / "share" / "flexure" / "python");
  }
#ifdef FLEXURE_INSTALL_DATADIR
  dirs.push_back(fs::path(FLEXURE_INSTALL_DATADIR) / "flexure" / "python");
#endif
  return dirs;
}

fs::path find_plot_module() {
  std::string looked;
  for (const fs::path& dir : plot_module_candidates()) {
    std::error_code ec;
    if (fs::is_regular_file(dir / "flexure_plot" / "__main__.py", ec)) return dir;
    looked += (looked.empty() ? "" : ", ") + dir.string();
  }
  throw std::runtime_error(fmt::format(
      "plot: the plot module flexure_plot is not installed (looked in {}); build the tool with "
      "CMake (it copies python/flexure_plot to build/share/flexure/python) or set "
      "FLEXURE_PLOT_PATH to the folder that holds flexure_plot/",
      looked));
}

// $FLEXURE_PYTHON, else Debian's /usr/bin/python3 (whose matplotlib and h5py the module uses),
// else python3 on the PATH.
std::string python_interpreter() {
  if (const char* env = std::getenv("FLEXURE_PYTHON"); env != nullptr && *env != '\0') return env;
  if (::access("/usr/bin/python3", X_OK) == 0) return "/usr/bin/python3";
  return "python3";
}

// Runs the module with `args`; returns its exit code and its stdout (one JSON object: the result
// or {"error", "exit_code"}). stderr is the tool's (warnings pass through).
int run_module(const fs::path& dir, const std::vector<std::string>& args, std::string& output) {
  const std::string python = python_interpreter();
  std::vector<std::string> words = {python, "-m", "flexure_plot"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);

  // The environment with the module's folder first on PYTHONPATH.
  std::string pythonpath = "PYTHONPATH=" + dir.string();
  if (const char* old = std::getenv("PYTHONPATH"); old != nullptr && *old != '\0') {
    pythonpath += std::string(":") + old;
  }
  std::vector<char*> env;
  for (char** e = environ; *e != nullptr; ++e) {
    if (std::strncmp(*e, "PYTHONPATH=", 11) != 0) env.push_back(*e);
  }
  env.push_back(pythonpath.data());
  env.push_back(nullptr);

  int pipe_fd[2];
  if (::pipe(pipe_fd) != 0) throw std::runtime_error("plot: cannot create a pipe");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addclose(&actions, pipe_fd[0]);
  posix_spawn_file_actions_adddup2(&actions, pipe_fd[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, pipe_fd[1]);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, python.c_str(), &actions, nullptr, argv.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipe_fd[1]);
  if (rc != 0) {
    ::close(pipe_fd[0]);
    throw std::runtime_error(fmt::format(
        "plot: cannot run the Python interpreter '{}' ({}); install python3 with the Debian "
        "packages python3-matplotlib and python3-h5py, or set FLEXURE_PYTHON",
        python,
        std::strerror(rc)));
  }
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(pipe_fd[0], buffer, sizeof buffer);
    if (n > 0) {
      output.append(buffer, static_cast<size_t>(n));
    } else if (n == 0 || errno != EINTR) {
      break;
    }
  }
  ::close(pipe_fd[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

void run_plot(const PlotArgs& a) {
  const fs::path dir = find_plot_module();
  std::vector<std::string> args = {a.file, "--front-end-json"};
  if (!a.out.empty()) args.insert(args.end(), {"--out", a.out});
  if (!a.animate.empty()) args.insert(args.end(), {"--animate", a.animate});
  if (!a.dump_json.empty()) args.insert(args.end(), {"--dump-json", a.dump_json});
  // The module refuses either for a file of another kind (exit 2), naming the kind.
  if (a.no_stress) args.emplace_back("--no-stress");
  if (a.n_option != nullptr && a.n_option->count() > 0) {
    if (!std::isfinite(a.n)) throw InvalidInput(fmt::format("--n must be finite, got {}", a.n));
    args.insert(args.end(), {"--n", fmt::format("{:.17g}", a.n)});
  }
  std::string output;
  const int code = run_module(dir, args, output);
  Json answer;
  try {
    answer = Json::parse(output);
  } catch (const std::exception&) {
    throw std::runtime_error(fmt::format(
        "plot: the plot module ({}/flexure_plot) stopped with exit code {} without an answer; "
        "see the messages above",
        dir.string(),
        code));
  }
  if (code != 0 || answer.contains("error")) {
    const std::string message = answer.value("error", std::string("the plot module failed"));
    if (answer.value("exit_code", code) == kExitInvalidInput) throw InvalidInput(message);
    throw std::runtime_error(message);
  }
  if (a.json) {
    print_json(answer);
    return;
  }
  std::cout << fmt::format(
      "{}: {}\n", answer.value("kind", std::string()), answer.value("description", std::string()));
  for (const auto& written : answer.value("written", Json::array())) {
    std::cout << "wrote " << written.get<std::string>() << "\n";
  }
}

}  // namespace

void register_plot_command(CLI::App& app) {
  auto args = std::make_shared<PlotArgs>();
  CLI::App* cmd = app.add_subcommand(
      "plot", "Plot any HDF5 file flexure writes (matplotlib and h5py under /usr/bin/python3)");
  cmd->add_option("file", args->file, "HDF5 file written by flexure")->required();
  cmd->add_option("--out",
                  args->out,
                  "Figure to write: .png, .pdf or .svg (default: FILE with .png in place of .h5)");
  cmd->add_option("--animate",
                  args->animate,
                  "Also write an animation of the deformed shapes (.gif; path files with "
                  "--shapes, mechanism strokes)");
  cmd->add_option("--dump-json",
                  args->dump_json,
                  "Write the plotted arrays (in the file's units) as JSON, for checks");
  cmd->add_flag("--no-stress",
                args->no_stress,
                "Mechanism strokes (`mechanism analyze --out`): leave out the stress panel");
  args->n_option = cmd->add_option("--n",
                                   args->n,
                                   "Models maps (`models map --out`): the load ratio n of the "
                                   "plane drawn, one of the file's n (default: the n nearest 0)");
  cmd->add_flag("--json",
                args->json,
                "Print one JSON object: {file, kind, description, out, animate, written}");
  cmd->callback([args] { run_plot(*args); });
}

}  // namespace flexure::cli
