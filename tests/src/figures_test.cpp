// src/figures/: quoting for gnuplot scripts, the shared figure style, and rendering a PNG.
#include <gtest/gtest.h>

#include "src/figures/gnuplot.h"
#include "src/figures/style.h"
#include "tests/src/test_util.h"

namespace colav {
namespace {

using testing_util::ReadFile;
using testing_util::TemporaryFolder;
using testing_util::UserErrorMessage;

TEST(Gnuplot, QuotesSingleQuotesByDoublingThem) {
  EXPECT_EQ(GnuplotQuote("plain"), "'plain'");
  EXPECT_EQ(GnuplotQuote("it's"), "'it''s'");
  EXPECT_EQ(GnuplotQuote(""), "''");
}

TEST(Gnuplot, EscapesEnhancedTextControlCharacters) {
  EXPECT_EQ(GnuplotEnhancedText("conv_vae beta^2 @x &y ~z {a} \\"),
            "conv\\_vae beta\\^2 \\@x \\&y \\~z \\{a\\} \\\\");
  EXPECT_EQ(GnuplotEnhancedText("no control (%)"), "no control (%)");
}

TEST(FigureStyle, PaletteRepeatsAfterEightColours) {
  EXPECT_EQ(FigureColour(0), "#0072b2");
  EXPECT_EQ(FigureColour(1), "#d55e00");
  EXPECT_EQ(FigureColour(8), FigureColour(0));
}

TEST(FigureStyle, ScriptSnippets) {
  EXPECT_EQ(LineColour("#0072b2"), "lc rgb '#0072b2'");
  EXPECT_EQ(LightGrid(), "set grid lc rgb '#dddddd'\n");
  EXPECT_EQ(MultiplotLayout(2, 3, "a 'b'"), "set multiplot layout 2,3 title 'a ''b'''\n");
  EXPECT_EQ(MultiplotLayout(1, 4, "t", 13), "set multiplot layout 1,4 title 't' font ',13'\n");
}

TEST(Gnuplot, RendersAPngAndLeavesNoTemporaryFiles) {
  const TemporaryFolder folder;
  RenderGnuplotPng(LightGrid() + "set title " + GnuplotQuote("x_1") + "\nplot sin(x) " +
                       LineColour(FigureColour(0)),
                   folder / "sine.png", 300, 200);
  EXPECT_EQ(ReadFile(folder / "sine.png").substr(1, 3), "PNG");
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{"sine.png"});
}

TEST(Gnuplot, FailureNamesThePngAndGnuplotsError) {
  const TemporaryFolder folder;
  const std::string message =
      UserErrorMessage([&] { RenderGnuplotPng("plot no_such_function(x)", folder / "bad.png"); });
  EXPECT_EQ(message.rfind((folder / "bad.png").string() + ": gnuplot failed: ", 0), 0U) << message;
  EXPECT_FALSE(std::filesystem::exists(folder / "bad.png"));
}

}  // namespace
}  // namespace colav
