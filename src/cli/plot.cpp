#include "cli/plot.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace impact::cli {
namespace {

struct Panel {
  const char* ylabel;
  const char* style;  // N is an impulse per step (the row at t_l carries N^{l-1}): drawn as such
};

const std::map<std::string, Panel> kPanels = {
    {"u", {"u(t) [m]", "lines lw 1.5"}},
    {"v", {"v(t) [m/s]", "lines lw 1.5"}},
    {"N", {"N(t) [m/s^2]", "impulses lw 1.5"}},
    {"E", {"E(t) = v^2/2 - f u [J/kg]", "lines lw 1.5"}},
    {"iterations", {"iterations per step", "impulses"}},
};

std::string quoted(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string plot_script(const std::string& csv, const std::string& header, const std::string& out) {
  std::vector<std::string> columns;
  std::stringstream fields(header);
  for (std::string f; std::getline(fields, f, ',');) columns.push_back(f);
  if (columns.size() < 2 || columns[0] != "t")
    throw std::invalid_argument(csv + ": not a CSV of impact run (its header is '" + header +
                                "', expected t,<channels>)");
  const auto dot = out.rfind('.');
  const std::string ext = dot == std::string::npos ? "" : out.substr(dot + 1);
  std::string terminal;
  const int rows = static_cast<int>(columns.size()) - 1;
  if (ext == "png")
    terminal = "pngcairo size 1000," + std::to_string(260 * rows + 60) + " font ',10'";
  else if (ext == "pdf")
    terminal = "pdfcairo size 7in," + std::to_string(2 * rows + 1) + "in font ',8'";
  else if (ext == "svg")
    terminal = "svg size 1000," + std::to_string(260 * rows + 60) + " dynamic font ',10'";
  else
    throw std::invalid_argument(out + ": --out must end in .png, .pdf or .svg");
  std::ostringstream gp;
  gp << "set terminal " << terminal << "\nset output " << quoted(out)
     << "\nset datafile separator ','\nset grid\nset key off\n"
     << "set multiplot layout " << rows << ",1 title " << quoted(csv) << " noenhanced\n"
     << "set xlabel 't [s]'\n";
  for (std::size_t c = 1; c < columns.size(); ++c) {
    const auto panel = kPanels.find(columns[c]);
    if (panel == kPanels.end())
      throw std::invalid_argument(csv + ": unknown channel '" + columns[c] + "' in the header");
    gp << "set ylabel " << quoted(panel->second.ylabel) << "\nplot " << quoted(csv)
       << " using 1:" << c + 1 << " skip 1 with " << panel->second.style << " lc rgb '#0072B2'\n";
  }
  gp << "unset multiplot\n";
  return gp.str();
}

int plot_command(const std::string& csv, const std::string& out) {
  std::ifstream in(csv);
  std::string header;
  if (!in || !std::getline(in, header)) {
    std::fprintf(stderr, "impact: error: %s: cannot read the CSV\n", csv.c_str());
    return 2;
  }
  std::string script;
  try {
    script = plot_script(csv, header, out);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "impact: error: %s\n", e.what());
    return 2;
  }
  std::FILE* gnuplot = popen("gnuplot", "w");
  if (!gnuplot) {
    std::fprintf(stderr, "impact: error: cannot start gnuplot (install gnuplot-nox)\n");
    return 1;
  }
  std::fputs(script.c_str(), gnuplot);
  const int status = pclose(gnuplot);
  if (status != 0) {
    std::fprintf(stderr, "impact: error: gnuplot failed on %s (status %d)\n", csv.c_str(), status);
    return 1;
  }
  return 0;
}

}  // namespace impact::cli
