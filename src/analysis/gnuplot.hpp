#pragma once
// Charts through gnuplot (Debian package gnuplot-nox, pngcairo terminal): a well-kept charting tool,
// driven through a pipe. Each chart is a script with its data inlined as datablocks ($name << EOD), saved
// beside the PNG so it can be re-rendered or restyled by hand: `gnuplot chart.gp`.

#include <string>
#include <vector>

namespace sl {

// True when a `gnuplot` executable with the pngcairo terminal is on the PATH.
bool gnuplotAvailable();

// A datablock definition: "$name << EOD\n" + lines + "EOD\n". Lines are whitespace-separated columns.
std::string gnuplotDatablock(const std::string& name, const std::vector<std::string>& lines);

// A number in a datablock column: shortest round-trip digits, or NaN (gnuplot's undefined value, so the point is
// skipped and the columns stay aligned) for a non-finite one.
std::string gnuplotNumber(double value);

// Quotes text for a gnuplot string literal (single quotes; embedded quotes doubled).
std::string gnuplotQuote(const std::string& text);

// The preamble every chart starts with: pngcairo at width x height, DejaVu Sans, output to pngPath.
std::string gnuplotPngPreamble(const std::string& pngPath, int width, int height);

// Writes the script next to the PNG (pngPath with .gp) and pipes it to gnuplot. Throws
// std::runtime_error with gnuplot's exit status when it fails or is missing.
void renderGnuplotChart(const std::string& script, const std::string& pngPath);

// The chart formats besides PNG, for papers: "svg" (gnuplot's svg terminal) and "pdf" (pdfcairo), at the PNG's
// size (100 pixels an inch for PDF). Parses "svg,pdf"; throws std::invalid_argument naming what is allowed.
std::vector<std::string> parseChartFormats(const std::string& list);

// The file of a chart in another format or its script: pngPath with the extension ".gp", ".svg", ".pdf".
std::string chartCompanion(const std::string& pngPath, const std::string& extension);
// Every file a chart writes: the PNG, its script and each of `formats` (for the output checks before any work).
std::vector<std::string> chartFiles(const std::string& pngPath, const std::vector<std::string>& formats);

// Renders the chart pngPath was made from (its script, pngPath with .gp) again in each format, beside it
// (pngPath with .svg / .pdf); returns the files written. Throws std::runtime_error as renderGnuplotChart.
std::vector<std::string> renderChartAs(const std::string& pngPath, const std::vector<std::string>& formats);

}  // namespace sl
