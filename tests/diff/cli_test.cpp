// The glpt executable: help texts, `glpt run` (environment, preload, exit status), `glpt record`
// (the apitrace command line) and `glpt replay` (glpt-replay next to glpt), run as processes.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "commands.hpp"
#include "quality_flags.hpp"
#include "shell.hpp"
#include "temp_dir.hpp"

namespace glpt::cli {
namespace {

namespace fs = std::filesystem;

const std::string kGlpt = GLPT_CLI_EXE;
// A shared library that loads and does nothing (tests/diff/fake_preload.c).
const std::string kFakeLib = GLPT_FAKE_PRELOAD;

class Cli : public ::testing::Test {
 protected:
  void script(const std::string& path, const std::string& body) {
    std::ofstream(path) << "#!/bin/sh\n" << body << "\n";
    fs::permissions(path, fs::perms::owner_all);
  }
  glpt::testing::ScopedTempDir temp_{"glpt_cli"};
  const std::string dir_ = temp_.path();
};

TEST_F(Cli, HelpForEveryCommand) {
  Result top = shell(kGlpt + " --help");
  EXPECT_EQ(top.status, 0);
  for (const Command& c : commands()) {
    EXPECT_NE(top.out.find("  " + std::string(c.name) + " "), std::string::npos) << c.name;
    const Result help = shell(kGlpt + " help " + std::string(c.name));
    EXPECT_EQ(help.status, 0) << c.name;
    EXPECT_EQ(help.out, c.help()) << c.name;
    if (c.name != "replay") {  // glpt replay --help is glpt-replay's own when that is built
      const Result flag = shell(kGlpt + " " + std::string(c.name) + " --help");
      EXPECT_EQ(flag.status, 0) << c.name;
      EXPECT_EQ(flag.out, help.out) << c.name;
    }
  }
  EXPECT_EQ(shell(kGlpt).status, 2);
  EXPECT_EQ(shell(kGlpt + " frobnicate").status, 2);
  EXPECT_EQ(shell(kGlpt + " help frobnicate").status, 2);
}

TEST_F(Cli, RunHelpListsEveryQualityFlag) {
  const std::string help = run_help();
  for (const QualityFlag& f : quality_flags()) {
    EXPECT_NE(help.find(std::string(f.flag)), std::string::npos) << f.flag;
    // Appended, not `"[" + std::string(...)`: GCC 12 -O3 reports a false -Wrestrict there (GCC
    // bug 105329), which fails the Release build under -Werror.
    const std::string bracketed = std::string("[").append(f.variable).append("]");
    EXPECT_NE(help.find(bracketed), std::string::npos) << f.variable;
  }
}

TEST(QualityFlags, ParsesEveryForm) {
  const std::vector<std::string> args = {
      "--spp", "4",        "--mode=raster", "--stats",         "--light-size-deg",
      "0.5",   "--output", "/tmp/x",        "--no-accumulate", "prog"};
  EnvSettings env;
  std::string error;
  size_t i = 0;
  while (parse_quality_flag(args, &i, &env, &error) == FlagParse::kParsed) {
  }
  EXPECT_EQ(i, 9u);  // stopped at "prog"
  EXPECT_EQ(env, (EnvSettings{{"GLPT_SPP", "4"},
                              {"GLPT_MODE", "raster"},
                              {"GLPT_STATS", "1"},
                              {"GLPT_LIGHT_SIZE_DEG", "0.5"},
                              {"GLPT_OUTPUT", "/tmp/x"},
                              {"GLPT_ACCUMULATE", "0"}}));
}

TEST(QualityFlags, RejectsBadValues) {
  for (const std::vector<std::string>& bad :
       std::vector<std::vector<std::string>>{{"--spp", "four"},
                                             {"--spp", "-1"},
                                             {"--spp"},
                                             {"--mode", "fast"},
                                             {"--light-size-deg", "nan"},
                                             {"--stats=1"},
                                             {"--output="}}) {
    EnvSettings env;
    std::string error;
    size_t i = 0;
    EXPECT_EQ(parse_quality_flag(bad, &i, &env, &error), FlagParse::kError) << bad[0];
    EXPECT_NE(error.find(bad[0].substr(0, bad[0].find('='))), std::string::npos) << error;
    EXPECT_TRUE(env.empty());
  }
  EnvSettings env;
  std::string error;
  size_t i = 0;
  const std::vector<std::string> other = {"--lib", "x"};
  EXPECT_EQ(parse_quality_flag(other, &i, &env, &error), FlagParse::kNotAQualityFlag);
  EXPECT_EQ(i, 0u);
}

TEST_F(Cli, RunSetsTheEnvironmentAndPassesTheExitStatusThrough) {
  // Any library that loads will do here.
  const std::string lib = dir_ + "/libGL.so.1";
  fs::copy_file(kFakeLib, lib);
  const std::string probe = dir_ + "/probe.sh";
  script(probe,
         "echo \"spp=$GLPT_SPP mode=$GLPT_MODE acc=$GLPT_ACCUMULATE preload=$LD_PRELOAD "
         "args=$*\"; exit 3");
  const Result r = shell("LD_PRELOAD= " + kGlpt + " run --spp 4 --mode raster --no-accumulate " +
                         "--lib " + lib + " -- " + probe + " one --spp");
  EXPECT_EQ(r.status, 3) << r.out;
  EXPECT_NE(r.out.find("spp=4 mode=raster acc=0 preload=" + lib + " args=one --spp"),
            std::string::npos)
      << r.out;
  // Without "--" the program starts at the first argument that is not an option.
  const Result bare = shell("LD_PRELOAD= " + kGlpt + " run --lib " + lib + " " + probe);
  EXPECT_EQ(bare.status, 3) << bare.out;
}

TEST_F(Cli, RunErrors) {
  const std::string lib = dir_ + "/libGL.so.1";
  fs::copy_file(kFakeLib, lib);
  EXPECT_EQ(shell(kGlpt + " run --spp x --lib " + lib + " -- true").status, 2);
  EXPECT_EQ(shell(kGlpt + " run --lib " + lib).status, 2);  // no program
  EXPECT_EQ(shell(kGlpt + " run --lib " + dir_ + "/absent.so -- true").status, 2);
  EXPECT_EQ(shell(kGlpt + " run --frobnicate -- true").status, 2);
  const Result missing = shell(kGlpt + " run --lib " + lib + " -- " + dir_ + "/no_such_program");
  EXPECT_EQ(missing.status, 127);
  EXPECT_NE(missing.out.find("no_such_program"), std::string::npos) << missing.out;
}

// The dynamic linker skips a preload it cannot load with a warning, and the program would run on
// the system's libGL as if nothing were wrong: glpt run refuses, and says what to do.
TEST_F(Cli, RunRefusesALibraryThatCannotBeLoaded) {
  const std::string lib = dir_ + "/libGL.so.1";
  std::ofstream(lib) << "not a library";
  const Result r = shell(kGlpt + " run --lib " + lib + " -- true");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("cannot be loaded"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("glpt doctor"), std::string::npos) << r.out;
}

TEST_F(Cli, RunFindsTheLibraryNextToGlpt) {
  // Build tree: BUILD/replay/glpt and BUILD/gl_shim/libGL.so.1.
  fs::create_directories(dir_ + "/build/replay");
  fs::create_directories(dir_ + "/build/gl_shim");
  EXPECT_EQ(find_glpt_library(dir_ + "/build/replay"), "");
  fs::copy_file(kFakeLib, dir_ + "/build/gl_shim/libGL.so.1");
  EXPECT_EQ(find_glpt_library(dir_ + "/build/replay"),
            dir_ + "/build/replay/../gl_shim/libGL.so.1");
  // Installed: PREFIX/bin/glpt and PREFIX/lib/glpt/libGL.so.1.
  fs::create_directories(dir_ + "/prefix/bin");
  fs::create_directories(dir_ + "/prefix/lib/glpt");
  std::ofstream(dir_ + "/prefix/lib/glpt/libGL.so.1") << "x";
  EXPECT_EQ(find_glpt_library(dir_ + "/prefix/bin"), dir_ + "/prefix/bin/../lib/glpt/libGL.so.1");

  // And the executable uses it: a copy of glpt in the fake build tree preloads that file.
  fs::copy_file(kGlpt, dir_ + "/build/replay/glpt");
  const Result r =
      shell("LD_PRELOAD= " + dir_ + "/build/replay/glpt run -- sh -c 'echo \"[$LD_PRELOAD]\"'");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("[" + dir_ + "/build/replay/../gl_shim/libGL.so.1]"), std::string::npos)
      << r.out;
  // Without one, a clear error.
  fs::copy_file(kGlpt, dir_ + "/glpt");
  const Result none = shell(dir_ + "/glpt run -- true");
  EXPECT_EQ(none.status, 2);
  EXPECT_NE(none.out.find("--lib"), std::string::npos) << none.out;
}

TEST_F(Cli, RecordRunsApitrace) {
  const std::string bin = dir_ + "/bin";
  fs::create_directories(bin);
  script(bin + "/apitrace", "echo \"apitrace $*\"; exit 5");
  const Result r = shell("PATH=" + bin + ":/usr/bin:/bin " + kGlpt +
                         " record --api egl -o out.trace -- prog --flag arg");
  EXPECT_EQ(r.status, 5) << r.out;
  EXPECT_NE(r.out.find("apitrace trace --api egl --output out.trace prog --flag arg"),
            std::string::npos)
      << r.out;
  const Result defaults = shell("PATH=" + bin + ":/usr/bin:/bin " + kGlpt + " record prog");
  EXPECT_NE(defaults.out.find("apitrace trace --api gl prog"), std::string::npos) << defaults.out;
  EXPECT_EQ(shell("PATH=" + bin + " " + kGlpt + " record --api glx prog").status, 2);
  EXPECT_EQ(shell("PATH=" + bin + " " + kGlpt + " record -o").status, 2);
}

TEST_F(Cli, RecordWithoutApitrace) {
  const Result r = shell("PATH=" + dir_ + " " + kGlpt + " record -o x.trace -- prog");
  EXPECT_EQ(r.status, 127);
  EXPECT_NE(r.out.find("apitrace was not found"), std::string::npos) << r.out;
}

TEST_F(Cli, ReplayRunsGlptReplayNextToGlpt) {
  fs::copy_file(kGlpt, dir_ + "/glpt");
  const Result missing = shell(dir_ + "/glpt replay some.trace");
  EXPECT_EQ(missing.status, 127);
  EXPECT_NE(missing.out.find("glpt-replay was not found next to glpt"), std::string::npos)
      << missing.out;
  EXPECT_EQ(shell(dir_ + "/glpt replay --help").status, 0);
  script(dir_ + "/glpt-replay", "echo \"replay $*\"; exit 4");
  const Result r = shell(dir_ + "/glpt replay some.trace --frames 1-3");
  EXPECT_EQ(r.status, 4) << r.out;
  EXPECT_NE(r.out.find("replay some.trace --frames 1-3"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace glpt::cli
