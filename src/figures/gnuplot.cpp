#include "src/gnuplot.h"

#include <cstdio>
#include <fstream>
#include <sstream>

#include "src/atomic_file.h"
#include "src/error.h"

namespace colav {
namespace {

std::string ShellQuote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += "'\\''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

}  // namespace

std::string GnuplotQuote(const std::string& text) {
  std::string quoted = "'";
  for (const char c : text) {
    if (c == '\'') {
      quoted += "''";
    } else {
      quoted += c;
    }
  }
  return quoted + "'";
}

void RenderGnuplotPng(const std::string& script, const std::filesystem::path& png, int width,
                      int height) {
  WriteFileAtomically(png, [&](const std::filesystem::path& temporary) {
    const std::filesystem::path script_path = temporary.string() + ".gp";
    const std::filesystem::path log_path = temporary.string() + ".log";
    {
      std::ofstream out(script_path);
      out << "set terminal pngcairo size " << width << "," << height
          << " enhanced font 'Sans,10'\nset output " << GnuplotQuote(temporary.string()) << "\n"
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
