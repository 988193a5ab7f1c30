#include "src/figures/gnuplot.h"

#include <cstdlib>
#include <fstream>
#include <string>

#include "src/atomic_file.h"
#include "src/error.h"
#include "src/figures/style.h"

namespace colav {
namespace {

// `text` in single quotes, each single quote in it written as `escaped_quote`.
std::string SingleQuote(const std::string& text, const std::string& escaped_quote) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += escaped_quote;
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

std::string ShellQuote(const std::string& text) { return SingleQuote(text, "'\\''"); }

}  // namespace

std::string GnuplotQuote(const std::string& text) { return SingleQuote(text, "''"); }

std::string GnuplotEnhancedText(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (std::string("_^@&~{}\\").find(c) != std::string::npos) escaped += '\\';
    escaped += c;
  }
  return escaped;
}

void RenderGnuplotPng(const std::string& script, const std::filesystem::path& png, int width,
                      int height) {
  WriteFileAtomically(png, [&](const std::filesystem::path& temporary) {
    const std::filesystem::path script_path = temporary.string() + ".gp";
    const std::filesystem::path log_path = temporary.string() + ".log";
    {
      std::ofstream out(script_path);
      out << "set terminal pngcairo size " << width << "," << height << " enhanced font "
          << GnuplotQuote(kFigureFont) << "\nset output " << GnuplotQuote(temporary.string())
          << "\n"
          << script << "\nset output\n";
    }
    const std::string command =
        "gnuplot " + ShellQuote(script_path.string()) + " 2> " + ShellQuote(log_path.string());
    const int status = std::system(command.c_str());
    std::string first_error;
    {
      std::ifstream log(log_path);
      std::getline(log, first_error);
    }
    std::filesystem::remove(script_path);
    std::filesystem::remove(log_path);
    if (status != 0 || !std::filesystem::exists(temporary)) {
      throw UserError(png.string() + ": gnuplot failed" +
                      (first_error.empty() ? " (is gnuplot installed?)" : ": " + first_error));
    }
  });
}

}  // namespace colav
