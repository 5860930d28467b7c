// gnuplot-driven CSV plots. See csv_plot.hpp.
#include "output/csv_plot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "output/atomic_file.hpp"

extern char** environ;

namespace plyimpact::output {
namespace fs = std::filesystem;
namespace {

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r\"");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r\"") - first + 1);
}

// gnuplot single-quoted string: no escapes except '' for a quote.
std::string quoted(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string join(const std::vector<std::string>& v) {
  std::string out;
  for (const auto& s : v) out += (out.empty() ? "" : ", ") + s;
  return out;
}

std::string script_for(const CsvPlot& p, const fs::path& out) {
  std::ostringstream s;
  s.precision(17);
  s << "set terminal pngcairo size " << p.width << "," << p.height << " enhanced font 'sans,11'\n"
    << "set output " << quoted(out.string()) << "\n"
    << "set datafile separator ','\n"
    << "set grid\nset key top left box opaque Left reverse width 2\n"
    << "set title " << quoted(p.title) << " noenhanced\n"
    << "set xlabel " << quoted(p.x_label.empty() ? p.x_column : p.x_label) << " noenhanced\n"
    << "set ylabel " << quoted(p.y_label.empty() ? p.series.front().y_column : p.y_label) << " noenhanced\n";
  if (p.log_x) s << "set logscale x\n";
  if (p.log_y) s << "set logscale y\n";
  s << "plot ";
  for (std::size_t i = 0; i < p.series.size(); ++i) {
    const PlotSeries& ser = p.series[i];
    const char* style = ser.points_only ? "points pointtype 7 pointsize 1.5"
                        : p.with_points  ? "linespoints pointsize 1.2 linewidth 2"
                                         : "lines linewidth 2";
    s << (i ? ", \\\n     " : "") << quoted((ser.csv.empty() ? p.csv : ser.csv).string()) << " using (column("
      << quoted(p.x_column) << ")*" << p.x_scale << "):(column(" << quoted(ser.y_column) << ")*" << p.y_scale
      << ") with " << style << " title "
      << quoted(ser.title.empty() ? ser.y_column : ser.title) << " noenhanced";
  }
  s << "\nunset output\n";
  return s.str();
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs `gnuplot script`, stdout and stderr to `log`; returns the exit status (-1: could not start).
int run_gnuplot(const fs::path& gnuplot, const fs::path& script, const fs::path& log) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  std::string prog = gnuplot.string(), arg = script.string();
  char* argv[] = {prog.data(), arg.data(), nullptr};
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, prog.c_str(), &actions, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

std::optional<fs::path> find_gnuplot() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const fs::path candidate = fs::path(dir) / "gnuplot";
    if (::access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return std::nullopt;
}

std::vector<std::string> csv_columns(const fs::path& csv) {
  std::ifstream in(csv);
  if (!in) throw InputError(msg() << csv.string() << ": cannot open the CSV file; allowed a path to a readable file");
  std::string line;
  while (std::getline(in, line)) {
    const std::string t = trim(line);
    if (t.empty() || t.front() == '#') continue;
    std::vector<std::string> names;
    std::stringstream fields(t);
    std::string f;
    while (std::getline(fields, f, ',')) names.push_back(trim(f));
    return names;
  }
  throw InputError(msg() << csv.string() << ": no header line; allowed a CSV whose first line names the columns");
}

void plot_csv_png(const CsvPlot& plot, const fs::path& png) {
  if (plot.series.empty()) throw InputError("a plot needs at least one y column");
  for (const auto& ser : plot.series) {
    const fs::path& csv = ser.csv.empty() ? plot.csv : ser.csv;
    const auto columns = csv_columns(csv);
    for (const auto& w : {plot.x_column, ser.y_column})
      if (std::find(columns.begin(), columns.end(), w) == columns.end())
        throw InputError(msg() << csv.string() << ": no column '" << w << "'; allowed one of " << join(columns));
  }
  gnuplot_png([&](const fs::path& tmp) { return script_for(plot, tmp); }, png, plot.csv.string());
}

void gnuplot_png(const std::function<std::string(const fs::path& tmp)>& script, const fs::path& png,
                 const std::string& what) {
  const auto gnuplot = find_gnuplot();
  if (!gnuplot)
    throw RunError(msg() << "cannot plot " << png.string()
                         << ": gnuplot is not on PATH (Debian package gnuplot-nox; tools/install-deps.sh installs it)");
  write_file_atomically(png, [&](const fs::path& tmp) {
    const fs::path script_file = tmp.string() + ".gp", log = tmp.string() + ".log";
    write_text_atomically(script_file, script(tmp));
    const int status = run_gnuplot(*gnuplot, script_file, log);
    std::string message = status == 0 ? std::string() : slurp(log);
    std::error_code ec;
    fs::remove(script_file, ec);
    fs::remove(log, ec);
    if (status != 0)
      throw RunError(msg() << "gnuplot failed (exit status " << status << ") plotting " << what << ": "
                           << trim(message));
    if (fs::file_size(tmp, ec) == 0) throw RunError(msg() << "gnuplot wrote an empty image for " << png.string());
  });
}

}  // namespace plyimpact::output
