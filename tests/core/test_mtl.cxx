// core/formats/mtl: what a .mtl's statements give, written here by hand after the MTL
// specification and the PBR extension's keys; every malformed line a warning "PATH:LINE:
// reason" with the rest of the file still read.
#include "core/error.h"
#include "core/formats/mtl.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <string>

namespace aniso
{
namespace
{
bool hasWarning(const MtlLibrary& library, const std::string& start, const std::string& part)
{
  for (const std::string& w : library.warnings)
  {
    if (w.rfind(start, 0) == 0 && w.find(part) != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

TEST(Mtl, ReadsTheClassicAndPbrStatementsOfEachMaterial)
{
  // Checks: every statement read into its field, keywords without case, comments, CRLF, a grey
  // Kd of one value, Tr as 1 - d, texture options before a file name with a space and
  // backslashes.
  const MtlLibrary library = parseMtl("# a comment\r\n"
                                      "newmtl red plastic\r\n"
                                      "  Kd 0.8 0.1 0.05   # trailing comment\r\n"
                                      "Ks 0.5 0.5 0.5\r\n"
                                      "Ns 96.5\r\n"
                                      "Tr 0.25\r\n"
                                      "illum 2\r\n"
                                      "Ka 0 0 0\r\n"
                                      "map_Kd -s 2 2 1 -bm 0.5 tex\\red paint.png\r\n"
                                      "MAP_BUMP -bm 2.5 height.png\r\n"
                                      "\n"
                                      "newmtl brushed\n"
                                      "kd 0.3\n"
                                      "Pr 0.4\n"
                                      "Pm 1\n"
                                      "Ps 0.2\n"
                                      "aniso 0.7\n"
                                      "anisor 0.125\n"
                                      "d -halo 0.5\n"
                                      "norm -clamp on -imfchan r normal.png\n"
                                      "map_Pm metal.png\n"
                                      "map_Pr rough.png\n"
                                      "map_Ks spec.png\n"
                                      "map_Ns shine.png\n",
                                      "lib.mtl");
  EXPECT_TRUE(library.warnings.empty()) << library.warnings.front();
  ASSERT_EQ(library.materials.size(), 2u);
  const MtlMaterial& red = library.materials[0];
  EXPECT_EQ(red.name, "red plastic");
  EXPECT_EQ(red.line, 2);
  EXPECT_EQ(*red.kd, (MtlColor{0.8, 0.1, 0.05}));
  EXPECT_EQ(*red.ks, (MtlColor{0.5, 0.5, 0.5}));
  EXPECT_DOUBLE_EQ(*red.ns, 96.5);
  EXPECT_DOUBLE_EQ(*red.opacity, 0.75);
  EXPECT_FALSE(red.hasPbrKeys());
  ASSERT_TRUE(red.mapKd);
  EXPECT_EQ(red.mapKd->file, "tex/red paint.png");
  EXPECT_TRUE(red.mapKd->transformed);
  EXPECT_DOUBLE_EQ(red.mapKd->bumpMultiplier, 0.5);
  EXPECT_EQ(red.mapKd->line, 9);
  ASSERT_TRUE(red.bump);
  EXPECT_EQ(red.bump->file, "height.png");
  EXPECT_DOUBLE_EQ(red.bump->bumpMultiplier, 2.5);
  EXPECT_FALSE(red.bump->transformed);

  const MtlMaterial* brushed = library.find("brushed");
  ASSERT_NE(brushed, nullptr);
  EXPECT_TRUE(brushed->hasPbrKeys());
  EXPECT_EQ(*brushed->kd, (MtlColor{0.3, 0.3, 0.3}));
  EXPECT_DOUBLE_EQ(*brushed->pr, 0.4);
  EXPECT_DOUBLE_EQ(*brushed->pm, 1.0);
  EXPECT_DOUBLE_EQ(*brushed->ps, 0.2);
  EXPECT_DOUBLE_EQ(*brushed->aniso, 0.7);
  EXPECT_DOUBLE_EQ(*brushed->anisor, 0.125);
  EXPECT_EQ(brushed->anisorLine, 18);
  EXPECT_DOUBLE_EQ(*brushed->opacity, 0.5);
  EXPECT_EQ(brushed->norm->file, "normal.png");
  EXPECT_EQ(brushed->mapPm->file, "metal.png");
  EXPECT_EQ(brushed->mapPr->file, "rough.png");
  EXPECT_EQ(brushed->mapKs->file, "spec.png");
  EXPECT_EQ(brushed->mapNs->file, "shine.png");
  EXPECT_EQ(library.find("nothing"), nullptr);
}

TEST(Mtl, EachMalformedLineIsAWarningNamingFileAndLineAndIsSkipped)
{
  // Checks: a line of each kind of fault warns "PATH:LINE:" and leaves the value before it; the
  // good lines around still count.
  const std::string text = "Kd 1 1 1\n"                    // 1: before any newmtl
                           "newmtl m\n"                    // 2
                           "Kd 0.2 0.3 0.4\n"              // 3
                           "Kd 1 2\n"                      // 4: two values
                           "Ks nan 0 0\n"                  // 5: not finite
                           "Ns -3\n"                       // 6: negative
                           "Ns 1e999\n"                    // 7: overflow
                           "d 1.5\n"                       // 8: out of [0, 1]
                           "Pr 0.5 0.6\n"                  // 9: too many
                           "Kd spectral green.rfl\n"       // 10: unsupported form
                           "frobnicate 3\n"                // 11: unknown statement
                           "map_Kd -bm\n"                  // 12: option without value
                           "map_Kd -zoom 3 a.png\n"        // 13: unknown option
                           "map_Kd -clamp on\n"            // 14: no file name
                           "map_Kd -o x a.png\n"           // 15: -o without a number
                           "Ns 12\n"                       // 16: fine
                           "newmtl\n"                      // 17: no name
                           "Kd 0 0 0\n"                    // 18: skipped silently
                           "newmtl m\n"                    // 19: repeated
                           "Kd 0 0 0\n"                    // 20: skipped silently
                           "newmtl n\n"                    // 21
                           "Ks 0x1p-2 0 0\n"               // 22: not a decimal number
                           "Ks +0.5 .25 1e-1\n"            // 23: fine
                           + std::string(5000, 'x') + "\n" // 24: too long
                           + std::string("Ns 1\0 2\n", 8); // 25: NUL
  const MtlLibrary library = parseMtl(text, "dir/bad.mtl");
  ASSERT_EQ(library.materials.size(), 2u);
  const MtlMaterial& m = library.materials[0];
  EXPECT_EQ(*m.kd, (MtlColor{0.2, 0.3, 0.4}));
  EXPECT_FALSE(m.ks);
  EXPECT_DOUBLE_EQ(*m.ns, 12.0);
  EXPECT_FALSE(m.opacity);
  EXPECT_FALSE(m.pr);
  EXPECT_FALSE(m.mapKd);
  const MtlMaterial& n = library.materials[1];
  EXPECT_EQ(*n.ks, (MtlColor{0.5, 0.25, 0.1}));
  EXPECT_FALSE(n.ns);
  for (int line : {1, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 17, 19, 22, 24, 25})
  {
    EXPECT_TRUE(hasWarning(library, "dir/bad.mtl:" + std::to_string(line) + ": ", ""))
        << "line " << line;
  }
  EXPECT_EQ(library.warnings.size(), 18u);
  EXPECT_TRUE(hasWarning(library, "dir/bad.mtl:4: ", "Kd: 1 or 3 values expected"));
  EXPECT_TRUE(hasWarning(library, "dir/bad.mtl:6: ", "Ns: -3 is outside [0,"));
  EXPECT_TRUE(hasWarning(library, "dir/bad.mtl:11: ", "unknown statement 'frobnicate'"));
  EXPECT_TRUE(hasWarning(library, "dir/bad.mtl:13: ", "unknown option -zoom"));
  EXPECT_TRUE(hasWarning(library, "dir/bad.mtl:19: ", "the first is kept"));
}

TEST(Mtl, NamesAndFileNamesMustBeUtf8)
{
  // Checks: a material name or texture file name that is not UTF-8 (a lone continuation byte,
  // an overlong '/', a surrogate, a truncated sequence) is a warning, the line skipped (they go
  // into JSON documents); UTF-8 names of two, three and four bytes are read.
  const MtlLibrary library =
      parseMtl("newmtl Stahl geb\xc3\xbcrstet \xe9\x8b\xbc \xf0\x9f\x94\xa9\n"
               "map_Kd \xe6\x9d\xbf.png\n"
               "newmtl bad\x80name\n"
               "newmtl over\xc0\xafong\n"
               "newmtl sur\xed\xa0\x80rogate\n"
               "newmtl cut\xe6\x9d\n"
               "newmtl ok\n"
               "map_Kd tex\xff.png\n",
               "u.mtl");
  ASSERT_EQ(library.materials.size(), 2u);
  EXPECT_EQ(library.materials[0].name, "Stahl geb\xc3\xbcrstet \xe9\x8b\xbc \xf0\x9f\x94\xa9");
  EXPECT_EQ(library.materials[0].mapKd->file, "\xe6\x9d\xbf.png");
  EXPECT_FALSE(library.materials[1].mapKd);
  for (int line : {3, 4, 5, 6, 8})
  {
    EXPECT_TRUE(hasWarning(library, "u.mtl:" + std::to_string(line) + ": ", "not UTF-8"))
        << "line " << line;
  }
  EXPECT_EQ(library.warnings.size(), 5u);
}

TEST(Mtl, WarningsAreCappedWithACountOfTheRest)
{
  // Checks: a file of 1000 bad lines keeps kMaxMtlWarnings warnings and one that counts the
  // other 900.
  std::string text = "newmtl m\n";
  for (int i = 0; i < 1000; ++i)
  {
    text += "Kd x\n";
  }
  const MtlLibrary library = parseMtl(text, "many.mtl");
  ASSERT_EQ(library.warnings.size(), kMaxMtlWarnings + 1);
  EXPECT_EQ(library.warnings.back(), "many.mtl: 900 more warnings");
}

TEST(Mtl, ReadsAFileAndRefusesWhatCannotBeRead)
{
  // Checks: readMtlFile reads the file's materials; a missing file and a directory are
  // aniso::Error naming the path.
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "aniso_test_mtl";
  std::filesystem::create_directories(dir);
  const std::string file = (dir / "one.mtl").string();
  std::ofstream(file) << "newmtl gold\nKd 1 0.8 0.3\n";
  const MtlLibrary library = readMtlFile(file);
  ASSERT_EQ(library.materials.size(), 1u);
  EXPECT_EQ(library.materials[0].name, "gold");
  for (const std::string& bad : {(dir / "missing.mtl").string(), dir.string()})
  {
    try
    {
      readMtlFile(bad);
      ADD_FAILURE() << bad << " was read";
    }
    catch (const Error& e)
    {
      EXPECT_EQ(std::string(e.what()).rfind(bad + ": ", 0), 0u) << e.what();
    }
  }
  std::filesystem::remove_all(dir);
}
} // namespace
} // namespace aniso
