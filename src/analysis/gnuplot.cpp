#include "analysis/gnuplot.hpp"

#include "analysis/csv_table.hpp"

#include <cmath>

#include <sys/wait.h>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <algorithm>
#include <iterator>

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

namespace {

void pipeToGnuplot(const std::string& script, const std::string& scriptPath) {
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

}  // namespace

std::string chartCompanion(const std::string& pngPath, const std::string& extension) {
  return std::filesystem::path(pngPath).replace_extension(extension).string();
}

std::vector<std::string> chartFiles(const std::string& pngPath, const std::vector<std::string>& formats) {
  std::vector<std::string> files{pngPath, chartCompanion(pngPath, ".gp")};
  for (const std::string& format : formats) files.push_back(chartCompanion(pngPath, "." + format));
  return files;
}

void renderGnuplotChart(const std::string& script, const std::string& pngPath) {
  const std::string scriptPath = chartCompanion(pngPath, ".gp");
  {
    std::ofstream out(scriptPath, std::ios::trunc);
    if (!out) throw std::runtime_error(scriptPath + ": cannot open for writing");
    out << script;
    out.close();
    if (!out) throw std::runtime_error(scriptPath + ": cannot write (disk full?)");
  }
  pipeToGnuplot(script, scriptPath);
}

std::vector<std::string> parseChartFormats(const std::string& list) {
  std::vector<std::string> formats;
  std::size_t start = 0;
  while (start <= list.size() && !list.empty()) {
    const std::size_t comma = list.find(',', start);
    const std::string format = list.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (format != "svg" && format != "pdf" && format != "png")
      throw std::invalid_argument("found \"" + format + "\"; expected svg, pdf or png, comma-separated");
    if (format != "png" && std::find(formats.begin(), formats.end(), format) == formats.end())
      formats.push_back(format);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return formats;
}

std::vector<std::string> renderChartAs(const std::string& pngPath, const std::vector<std::string>& formats) {
  const std::string scriptPath = chartCompanion(pngPath, ".gp");
  std::ifstream in(scriptPath);
  if (!in) throw std::runtime_error(scriptPath + ": cannot read the chart's script");
  const std::string script((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  // The preamble's two lines (gnuplotPngPreamble): "set terminal pngcairo size W,H ..." and "set output '...'".
  const std::string terminal = "set terminal pngcairo size ";
  const std::size_t at = script.find(terminal);
  const std::size_t lineEnd = at == std::string::npos ? at : script.find('\n', at);
  const std::size_t outputAt = lineEnd == std::string::npos ? lineEnd : script.find("set output ", lineEnd);
  const std::size_t outputEnd = outputAt == std::string::npos ? outputAt : script.find('\n', outputAt);
  if (outputEnd == std::string::npos) throw std::runtime_error(scriptPath + ": no pngcairo terminal to replace");
  int width = 0, height = 0;
  if (std::sscanf(script.c_str() + at + terminal.size(), "%d,%d", &width, &height) != 2)
    throw std::runtime_error(scriptPath + ": cannot read the chart's size");
  std::vector<std::string> written;
  for (const std::string& format : formats) {
    const std::string path = chartCompanion(pngPath, "." + format);
    char size[64];
    if (format == "pdf")
      std::snprintf(size, sizeof size, "%gin,%gin", width / 100.0, height / 100.0);
    else
      std::snprintf(size, sizeof size, "%d,%d", width, height);
    const std::string preamble = std::string("set terminal ") + (format == "pdf" ? "pdfcairo" : "svg") + " size " +
                                 size + (format == "svg" ? " dynamic background '#ffffff'" : "") +
                                 " enhanced font 'DejaVu Sans,10'\nset output " + gnuplotQuote(path);
    std::string other = script;
    other.replace(at, outputEnd - at, preamble);
    pipeToGnuplot(other, scriptPath);
    written.push_back(path);
  }
  return written;
}

}  // namespace sl
