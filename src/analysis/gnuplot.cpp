#include "analysis/gnuplot.hpp"

#include "analysis/csv_table.hpp"

#include <cmath>

#include <sys/wait.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace sl {

bool gnuplotAvailable() {
  FILE* pipe = popen("gnuplot -e \"set terminal pngcairo\" 2>/dev/null", "r");
  if (!pipe) return false;
  const int status = pclose(pipe);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

std::string gnuplotDatablock(const std::string& name, const std::vector<std::string>& lines) {
  std::string block = "$" + name + " << EOD\n";
  for (const auto& line : lines) block += line + "\n";
  return block + "EOD\n";
}

std::string gnuplotNumber(double value) { return std::isfinite(value) ? formatNumber(value) : "NaN"; }

std::string gnuplotQuote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += (c == '\'') ? std::string("''") : std::string(1, c);
  return quoted + "'";
}

std::string gnuplotPngPreamble(const std::string& pngPath, int width, int height) {
  return "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " enhanced font 'DejaVu Sans,10'\nset output " + gnuplotQuote(pngPath) + "\n";
}

void renderGnuplotChart(const std::string& script, const std::string& pngPath) {
  const std::string scriptPath = std::filesystem::path(pngPath).replace_extension(".gp").string();
  {
    std::ofstream out(scriptPath, std::ios::trunc);
    if (!out) throw std::runtime_error(scriptPath + ": cannot open for writing");
    out << script;
    out.close();
    if (!out) throw std::runtime_error(scriptPath + ": cannot write (disk full?)");
  }
  // gnuplot reads the script from the pipe; its own messages go to our stderr.
  FILE* pipe = popen("gnuplot", "w");
  if (!pipe) throw std::runtime_error("cannot start gnuplot (install the Debian package gnuplot-nox)");
  const bool sent = std::fwrite(script.data(), 1, script.size(), pipe) == script.size();
  const int status = pclose(pipe);
  if (!sent) throw std::runtime_error("cannot send " + scriptPath + " to gnuplot");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("gnuplot failed on " + scriptPath + " (exit status " +
                             std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) +
                             "; is gnuplot-nox installed?)");
}

}  // namespace sl
