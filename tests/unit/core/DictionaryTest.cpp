#include <gtest/gtest.h>

#include <filesystem>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "core/Real.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {
namespace {

namespace fs = std::filesystem;

const std::string dataDir = std::string(SPHCAST_TEST_DATA_DIR) + "/dictionary";

// Every test parses as if the text were a file named controlDict, so messages read
// "controlDict:line:column: ...".
Dictionary parse(std::string_view text) { return Dictionary::parse(text, "controlDict"); }

// The message of the DictionaryError that `action` throws; anything else fails the test.
std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const DictionaryError& error) {
    return error.what();
  }
  return "no error";
}

std::string parseError(std::string_view text) {
  return errorOf([text] { parse(text); });
}

const Dimensions kinematicViscosity{{0, 2, -1, 0, 0, 0, 0}};
const Dimensions acceleration{{0, 1, -2, 0, 0, 0, 0}};

// ---------------------------------------------------------------------------------------------
// Values of every supported type

TEST(Dictionary, ReadsNumbersInEveryWrittenForm) {
  const Dictionary dict =
      parse("a 1; b -2; c +3; d 2.5; e -1.5e-3; f 1E3; g .5; h -.25; i 1.; j 1e-400;");
  EXPECT_EQ(dict.get<double>("a"), 1.0);
  EXPECT_EQ(dict.get<double>("b"), -2.0);
  EXPECT_EQ(dict.get<double>("c"), 3.0);
  EXPECT_EQ(dict.get<double>("d"), 2.5);
  EXPECT_EQ(dict.get<double>("e"), -1.5e-3);
  EXPECT_EQ(dict.get<double>("f"), 1000.0);
  EXPECT_EQ(dict.get<double>("g"), 0.5);
  EXPECT_EQ(dict.get<double>("h"), -0.25);
  EXPECT_EQ(dict.get<double>("i"), 1.0);
  EXPECT_EQ(dict.get<double>("j"), 0.0);  // underflow reads as zero, as in C
  EXPECT_EQ(dict.get<float>("d"), 2.5f);
}

TEST(Dictionary, ReadsIntegersOfEveryWidthWhenIntegralAndInRange) {
  const Dictionary dict = parse("n 42; m -7; big 9000000000; e 1e3;");
  EXPECT_EQ(dict.get<int>("n"), 42);
  EXPECT_EQ(dict.get<int>("m"), -7);
  EXPECT_EQ(dict.get<long>("big"), 9000000000L);
  EXPECT_EQ(dict.get<long long>("big"), 9000000000LL);
  EXPECT_EQ(dict.get<std::size_t>("n"), 42u);
  EXPECT_EQ(dict.get<int>("e"), 1000);
}

TEST(Dictionary, ReadsBooleansInAllOpenFoamSpellings) {
  const Dictionary dict = parse("a yes; b no; c on; d off; e true; f false; g y; h n;");
  for (const char* key : {"a", "c", "e", "g"}) EXPECT_TRUE(dict.get<bool>(key)) << key;
  for (const char* key : {"b", "d", "f", "h"}) EXPECT_FALSE(dict.get<bool>(key)) << key;
}

TEST(Dictionary, ReadsWordsWithOpenFoamPunctuation) {
  const Dictionary dict = parse(
      "scheme div(phi,U); mixed a.b:c<d>-e_f; negative -foo; "
      "div(phi,U) Gauss; path constant/geometry;");
  EXPECT_EQ(dict.get<std::string>("scheme"), "div(phi,U)");
  EXPECT_EQ(dict.get<std::string>("mixed"), "a.b:c<d>-e_f");
  EXPECT_EQ(dict.get<std::string>("negative"), "-foo");
  EXPECT_EQ(dict.get<std::string>("div(phi,U)"), "Gauss");
  EXPECT_EQ(dict.get<std::string>("path"), "constant/geometry");
}

TEST(Dictionary, WordRightBeforeAnUnbalancedParenthesisIsAWordAndAList) {
  const Dictionary dict = parse("value uniform(0 0 1);");
  EXPECT_EQ(dict.keys(), std::vector<std::string>{"value"});
  EXPECT_EQ(errorOf([&] { dict.get<Vector>("value"); }),
            "controlDict:1:7: expected a vector (x y z) for 'value', found word 'uniform'");
}

TEST(Dictionary, ReadsQuotedStringsWithEscapes) {
  const Dictionary dict =
      parse(R"(a "two words"; b "say \"hi\""; c "back\\slash"; d "tab\there"; e "regex \d+"; )"
            "f \"line\\\ncontinued\"; g \"\"; \"quoted key\" 1;");
  EXPECT_EQ(dict.get<std::string>("a"), "two words");
  EXPECT_EQ(dict.get<std::string>("b"), "say \"hi\"");
  EXPECT_EQ(dict.get<std::string>("c"), "back\\slash");
  EXPECT_EQ(dict.get<std::string>("d"), "tab\there");
  EXPECT_EQ(dict.get<std::string>("e"), "regex \\d+");
  EXPECT_EQ(dict.get<std::string>("f"), "linecontinued");
  EXPECT_EQ(dict.get<std::string>("g"), "");
  EXPECT_EQ(dict.get<int>("quoted key"), 1);
}

TEST(Dictionary, ReadsVectors) {
  const Dictionary dict = parse("g (0 0 -9.81); p (1.5 -2);");
  EXPECT_EQ(dict.get<Vector>("g"), Vector(0, 0, -9.81));
  EXPECT_EQ(dict.get<Eigen::Vector2d>("p"), Eigen::Vector2d(1.5, -2));
}

TEST(Dictionary, ReadsListsOfNumbersWordsAndVectors) {
  const Dictionary dict = parse(
      "numbers (1 2.5 -3); counts (1 2 3); fields (T U \"p rgh\"); empty ();"
      "points ((0 0 0) (1 2 3)); nested ((1 2) () (3));");
  EXPECT_EQ(dict.get<std::vector<double>>("numbers"), (std::vector<double>{1, 2.5, -3}));
  EXPECT_EQ(dict.get<std::vector<int>>("counts"), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(dict.get<std::vector<std::string>>("fields"),
            (std::vector<std::string>{"T", "U", "p rgh"}));
  EXPECT_TRUE(dict.get<std::vector<double>>("empty").empty());
  EXPECT_EQ(dict.get<std::vector<Vector>>("points"),
            (std::vector<Vector>{Vector(0, 0, 0), Vector(1, 2, 3)}));
  EXPECT_EQ(dict.get<std::vector<std::vector<double>>>("nested"),
            (std::vector<std::vector<double>>{{1, 2}, {}, {3}}));
}

TEST(Dictionary, ReadsTablesAsTuples) {
  const Dictionary dict = parse(
      "density ((300 2700) (900 2400));\n"
      "velocity ((0 (0 0 1)) (1 (0 0 2)));\n"
      "mixed ((1 copper yes) (2 \"cast iron\" no));");
  using Row = std::tuple<double, double>;
  EXPECT_EQ((dict.get<std::vector<Row>>("density")), (std::vector<Row>{{300, 2700}, {900, 2400}}));
  using VectorRow = std::tuple<double, Vector>;
  EXPECT_EQ((dict.get<std::vector<VectorRow>>("velocity")),
            (std::vector<VectorRow>{{0, Vector(0, 0, 1)}, {1, Vector(0, 0, 2)}}));
  using MixedRow = std::tuple<int, std::string, bool>;
  EXPECT_EQ((dict.get<std::vector<MixedRow>>("mixed")),
            (std::vector<MixedRow>{{1, "copper", true}, {2, "cast iron", false}}));
}

TEST(Dictionary, CountedListsReadWithOrWithoutSpaceBeforeTheParenthesis) {
  const Dictionary dict = parse(
      "a 3(1 2 3); b 3\n(\n  1\n  2\n  3\n); c 2((0 0 0) (1 1 1)); d (2(1 2) 0());"
      "e ((0 0 1) 3(0 0 2)); f 0();");
  EXPECT_EQ(dict.get<std::vector<double>>("a"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(dict.get<std::vector<double>>("b"), (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(dict.get<std::vector<Vector>>("c").size(), 2u);
  EXPECT_EQ(dict.get<std::vector<std::vector<int>>>("d"),
            (std::vector<std::vector<int>>{{1, 2}, {}}));
  EXPECT_EQ(dict.get<std::vector<Vector>>("e")[1], Vector(0, 0, 2));
  EXPECT_TRUE(dict.get<std::vector<double>>("f").empty());
}

TEST(Dictionary, HugeCountIsCheckedWithoutAllocating) {
  EXPECT_EQ(parseError("p 999999999999(1);"),
            "controlDict:1:3: list for 'p' has 1 item but its count says 999999999999");
  EXPECT_EQ(parseError("p 99999999999999999999999999(1);"),
            "controlDict:1:3: list for 'p' has 1 item but its count says "
            "99999999999999999999999999");
}

// ---------------------------------------------------------------------------------------------
// Structure: sub-dictionaries, header, comments, order, duplicates

TEST(Dictionary, SubDictionariesHaveScopedNamesAndLocations) {
  const Dictionary dict = parse(
      "endTime 1;\n"
      "functions\n"
      "{\n"
      "    probes { type probes; }\n"
      "}\n");
  EXPECT_EQ(dict.name(), "controlDict");
  EXPECT_TRUE(dict.isDict("functions"));
  EXPECT_FALSE(dict.isDict("endTime"));
  EXPECT_FALSE(dict.isDict("absent"));
  const Dictionary& probes = dict.subDict("functions").subDict("probes");
  EXPECT_EQ(dict.subDict("functions").name(), "controlDict/functions");
  EXPECT_EQ(probes.name(), "controlDict/functions/probes");
  EXPECT_EQ(probes.location().str(), "controlDict:4:5");
  EXPECT_EQ(probes.location("type").str(), "controlDict:4:14");
  EXPECT_EQ(probes.get<std::string>("type"), "probes");
}

TEST(Dictionary, TopLevelNameIsTheFileStem) {
  EXPECT_EQ(Dictionary::parse("", "case/system/controlDict").name(), "controlDict");
  EXPECT_EQ(Dictionary::parse("").name(), "<string>");
  EXPECT_EQ(Dictionary::parse("").location().str(), "<string>:1:1");
}

TEST(Dictionary, FoamFileHeaderIsKeptApartFromTheKeys) {
  const Dictionary dict = parse(
      "FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }\n"
      "endTime 1;\n");
  ASSERT_NE(dict.header(), nullptr);
  EXPECT_EQ(dict.header()->get<std::string>("object"), "controlDict");
  EXPECT_EQ(dict.keys(), std::vector<std::string>{"endTime"});
  EXPECT_FALSE(dict.found("FoamFile"));
  EXPECT_EQ(parse("a 1;").header(), nullptr);
  EXPECT_EQ(parse("a { FoamFile { b 1; } }").subDict("a").keys(),
            std::vector<std::string>{"FoamFile"});  // only the top level holds a header
}

TEST(Dictionary, CommentsAreSkippedAndLocationsCountThem) {
  const Dictionary dict = parse(
      "/* a block comment\n"
      "   over two lines */ startTime 0; // trailing\n"
      "// a whole line\n"
      "\tendTime/*inline*/0.5;\n"
      "deltaT 1e-3;// no space\n");
  EXPECT_EQ(dict.keys(), (std::vector<std::string>{"startTime", "endTime", "deltaT"}));
  EXPECT_EQ(dict.location("startTime").str(), "controlDict:2:22");
  EXPECT_EQ(dict.location("endTime").str(), "controlDict:4:2");
  EXPECT_EQ(dict.get<double>("endTime"), 0.5);
  EXPECT_EQ(dict.get<double>("deltaT"), 1e-3);
}

TEST(Dictionary, KeysKeepFileOrderAndAMacroMergeMayOverride) {
  const Dictionary dict = parse("b 1; a 2;\nlater { b 3; }\n$later");
  EXPECT_EQ(dict.keys(), (std::vector<std::string>{"b", "a", "later"}));
  EXPECT_EQ(dict.get<int>("b"), 3);
  EXPECT_EQ(dict.location("b").str(), "controlDict:2:9");
}

// OpenFOAM overrides a key given twice silently; sphCast takes it for a mistake, unless the
// earlier or the later entry comes from an #include file or a $macro merge.
TEST(DictionaryError, KeyGivenTwiceInOneFileNamesBothLines) {
  EXPECT_EQ(parseError("b 1; a 2;\nb 3;"),
            "controlDict:2:1: duplicate key 'b' in controlDict: given at lines 1 and 2; remove "
            "one (a key may override only an entry of an #include file or of a $macro merge)");
  EXPECT_EQ(
      parseError("flow\n{\n    model none;\n    fluid metal;\n    model weaklyCompressible;\n}"),
      "controlDict:5:5: duplicate key 'model' in controlDict/flow: given at lines 3 and 5; "
      "remove one (a key may override only an entry of an #include file or of a $macro "
      "merge)");
  EXPECT_EQ(parseError("d { x 1; }\nd { x 2; }"),
            "controlDict:2:5: duplicate key 'x' in controlDict/d: given at lines 1 and 2; remove "
            "one (a key may override only an entry of an #include file or of a $macro merge)");
  EXPECT_EQ(parseError("e { u 1; }\ne 5;"),
            "controlDict:2:1: duplicate key 'e' in controlDict: given at lines 1 and 2; remove "
            "one (a key may override only an entry of an #include file or of a $macro merge)");
}

// As in OpenFOAM (#inputMode merge): a sub-dictionary given again adds its entries; none of
// them may repeat a value of the first (KeyGivenTwiceInOneFileNamesBothLines).
TEST(Dictionary, SubDictionaryGivenTwiceIsMerged) {
  const Dictionary dict = parse("d { x 1; y 2; }\nd { z 4; }");
  EXPECT_EQ(dict.subDict("d").keys(), (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(dict.subDict("d").get<int>("z"), 4);
}

TEST(Dictionary, SubDictionaryGivenAgainByAMacroMergeIsMerged) {
  const Dictionary dict = parse("d { x 1; y 2; } e { u 1; }\nmore { d { y 3; z 4; } e 5; }\n$more");
  const Dictionary& d = dict.subDict("d");
  EXPECT_EQ(d.keys(), (std::vector<std::string>{"x", "y", "z"}));
  EXPECT_EQ(d.get<int>("y"), 3);
  EXPECT_EQ(dict.get<int>("e"), 5);  // a value replaces a dictionary outright
}

TEST(Dictionary, SameFileIncludedTwiceOverridesWithoutComplaint) {
  const Dictionary dict = Dictionary::parse(
      "m { #include \"common/material\"\n#include \"common/material\"\n }", dataDir + "/main");
  EXPECT_EQ(dict.subDict("m").keys(), (std::vector<std::string>{"density", "viscosity"}));
}

TEST(Dictionary, StraySemicolonsAndEmptyValuesAreAccepted) {
  const Dictionary dict = parse(";; a 1;; b { c 2; }; empty ;");
  EXPECT_EQ(dict.keys(), (std::vector<std::string>{"a", "b", "empty"}));
  EXPECT_EQ(errorOf([&] { dict.get<double>("empty"); }),
            "controlDict:1:27: expected a number for 'empty', found nothing");
}

TEST(Dictionary, CopiesShareTheirContent) {
  const Dictionary original = parse("a { b 1; }");
  const Dictionary copy = original;
  EXPECT_EQ(copy.subDict("a").get<int>("b"), 1);
  EXPECT_EQ(Dictionary().keys().size(), 0u);
}

// ---------------------------------------------------------------------------------------------
// Dimensions

TEST(Dictionary, DimensionsAreOptionalAndCheckedOnlyWhenExpected) {
  const Dictionary dict = parse(
      "g [0 1 -2 0 0 0 0] (0 0 -9.81);\n"
      "nu 1e-6;\n"
      "oldStyle nu [0 2 -1 0 0 0 0] 2e-6;\n"
      "five [0 2 -1 0 0] 3e-6;\n");
  EXPECT_EQ(dict.get<Vector>("g", acceleration), Vector(0, 0, -9.81));
  EXPECT_EQ(dict.get<Vector>("g"), Vector(0, 0, -9.81));
  EXPECT_EQ(dict.get<double>("nu", kinematicViscosity), 1e-6);
  EXPECT_EQ(dict.get<double>("oldStyle", kinematicViscosity), 2e-6);
  EXPECT_EQ(dict.get<double>("five", kinematicViscosity), 3e-6);
}

TEST(Dictionary, DimensionsPrintAsOpenFoamWritesThem) {
  EXPECT_EQ(kinematicViscosity.str(), "[0 2 -1 0 0 0 0]");
  EXPECT_EQ((Dimensions{{0.5, -0.0, 0, 0, 0, 0, 0}}.str()), "[0.5 0 0 0 0 0 0]");
}

// ---------------------------------------------------------------------------------------------
// Macros

TEST(Dictionary, MacrosSubstituteEarlierValuesFromThisScopeOrOutward) {
  const Dictionary dict = parse(
      "T0 300;\n"
      "g (0 0 -9.81);\n"
      "copy $T0;\n"
      "braced ${T0};\n"
      "inList ($T0 400 $T0);\n"
      "inner { T0 500; own $T0; outer $..T0; top $:T0; }\n"
      "gravity $g;\n");
  EXPECT_EQ(dict.get<double>("copy"), 300);
  EXPECT_EQ(dict.get<double>("braced"), 300);
  EXPECT_EQ(dict.get<std::vector<double>>("inList"), (std::vector<double>{300, 400, 300}));
  EXPECT_EQ(dict.subDict("inner").get<double>("own"), 500);
  EXPECT_EQ(dict.subDict("inner").get<double>("outer"), 300);
  EXPECT_EQ(dict.subDict("inner").get<double>("top"), 300);
  EXPECT_EQ(dict.get<Vector>("gravity"), Vector(0, 0, -9.81));
}

TEST(Dictionary, ScopedMacrosReachIntoSubDictionaries) {
  const Dictionary dict = parse(
      "metal { liquidus 933; solid { rho 2700; } }\n"
      "a $metal.liquidus;\n"
      "b $metal.solid.rho;\n"
      "c $metal/solid/rho;\n"
      "deep { deeper { d $:metal.solid.rho; e $metal.liquidus; } }\n");
  EXPECT_EQ(dict.get<int>("a"), 933);
  EXPECT_EQ(dict.get<int>("b"), 2700);
  EXPECT_EQ(dict.get<int>("c"), 2700);
  EXPECT_EQ(dict.subDict("deep").subDict("deeper").get<int>("d"), 2700);
  EXPECT_EQ(dict.subDict("deep").subDict("deeper").get<int>("e"), 933);
}

TEST(Dictionary, DictionaryMacroMergesOrCopiesEntries) {
  const Dictionary dict = parse(
      "defaults { type probes; interval 10; }\n"
      "probes { $defaults interval 5; }\n"
      "copied $defaults;\n");
  const Dictionary& probes = dict.subDict("probes");
  EXPECT_EQ(probes.keys(), (std::vector<std::string>{"type", "interval"}));
  EXPECT_EQ(probes.get<std::string>("type"), "probes");
  EXPECT_EQ(probes.get<int>("interval"), 5);
  const Dictionary& copied = dict.subDict("copied");
  EXPECT_EQ(copied.name(), "controlDict/copied");
  EXPECT_EQ(copied.get<int>("interval"), 10);
}

TEST(Dictionary, MacroSeesTheValueAtTheTimeItIsRead) {
  const Dictionary dict = parse("later { a 2; }\na 1; b $a;\n$later");
  EXPECT_EQ(dict.get<int>("b"), 1);
  EXPECT_EQ(dict.get<int>("a"), 2);
}

// ---------------------------------------------------------------------------------------------
// Files and #include

TEST(Dictionary, ReadsACompleteFileWithHeaderAndInclude) {
  const Dictionary dict = Dictionary::read(dataDir + "/controlDict");
  EXPECT_EQ(dict.name(), "controlDict");
  EXPECT_EQ(dict.header()->get<std::string>("class"), "dictionary");
  EXPECT_EQ(dict.getChoice("stopAt", {"endTime", "writeNow", "noWriteNow"}), "endTime");
  EXPECT_EQ(dict.get<double>("endTime"), 0.5);
  EXPECT_TRUE(dict.get<bool>("adjustTimeStep"));
  const Dictionary& probes = dict.subDict("functions").subDict("probes");
  EXPECT_EQ(probes.name(), "controlDict/functions/probes");
  EXPECT_EQ(probes.get<std::vector<Vector>>("probeLocations")[1], Vector(0, 0, 0.2));
  EXPECT_EQ(probes.location("fields").str(), dataDir + "/common/functions:7:9");
  EXPECT_EQ(dict.keys().back(), "functions");
}

TEST(Dictionary, IncludedEntriesLandInTheIncludingScopeWithTheirOwnLocations) {
  const Dictionary dict = Dictionary::parse(
      "before 1;\n"
      "aluminium\n"
      "{\n"
      "    #include \"common/material\"\n"
      "    density 2650;  // overrides the included value\n"
      "}\n"
      "after 2;\n",
      dataDir + "/physicalProperties");
  const Dictionary& aluminium = dict.subDict("aluminium");
  EXPECT_EQ(aluminium.keys(), (std::vector<std::string>{"density", "viscosity"}));
  EXPECT_EQ(aluminium.get<int>("density"), 2650);
  EXPECT_EQ(aluminium.get<double>("viscosity", kinematicViscosity), 1e-6);
  EXPECT_EQ(aluminium.location("viscosity").str(), dataDir + "/common/material:3:1");
  EXPECT_EQ(aluminium.location("density").str(), dataDir + "/physicalProperties:5:5");
  EXPECT_EQ(dict.location("after").str(), dataDir + "/physicalProperties:7:1");
}

TEST(Dictionary, IncludeIfPresentSkipsAMissingFile) {
  const Dictionary dict =
      Dictionary::parse("#includeIfPresent \"noSuchFile\"\na 1;", dataDir + "/main");
  EXPECT_EQ(dict.keys(), std::vector<std::string>{"a"});
}

TEST(Dictionary, ErrorInsideAnIncludedFilePointsIntoIt) {
  EXPECT_EQ(errorOf([] { Dictionary::parse("#include \"brokenInclude\"", dataDir + "/main"); }),
            dataDir +
                "/brokenInclude:2:7: missing ')' before ';' in the value of 'y' (the list "
                "opened at line 2, column 3)");
}

TEST(Dictionary, MissingIncludeNamesTheIncludingFileAndTheMissingPath) {
  EXPECT_EQ(
      errorOf([] { Dictionary::parse("a 1;\n  #include \"missingFile\"\n", dataDir + "/main"); }),
      dataDir + "/main:2:3: cannot open #include file '" + dataDir + "/missingFile'");
}

// #includeEtc looks in $SPHCAST_ETC first, then in the source tree's etc/ (where
// etc/materials/iron is), and may stand inside a sub-dictionary's braces.
TEST(Dictionary, IncludeEtcReadsFromTheEtcFoldersInOrder) {
  const fs::path etc = fs::temp_directory_path() / "sphCastDictionaryIncludeEtc";
  fs::create_directories(etc / "materials");
  std::ofstream(etc / "materials" / "testOnly") << "density 1234;\n";
  ASSERT_EQ(setenv("SPHCAST_ETC", etc.c_str(), 1), 0);
  const Dictionary dict = Dictionary::parse(
      "a { #includeEtc \"materials/testOnly\" }\nmold { #includeEtc \"materials/iron\" }\n",
      "physicalProperties");
  EXPECT_EQ(dict.subDict("a").get<double>("density"), 1234);
  EXPECT_EQ(dict.subDict("a").location("density").file,
            (etc / "materials" / "testOnly").string());
  EXPECT_EQ(dict.subDict("mold").get<double>("density"), 7874);  // from the source tree
  unsetenv("SPHCAST_ETC");
  fs::remove_all(etc);
}

TEST(Dictionary, MissingIncludeEtcNamesTheDirectiveAndTheFoldersSearched) {
  const std::string message = errorOf(
      [] { Dictionary::parse("a 1;\n  #includeEtc \"materials/noSuchMaterial\"\n", "main"); });
  EXPECT_NE(message.find("main:2:3: #includeEtc file 'materials/noSuchMaterial' is in none of "
                         "the sphCast etc folders"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find(std::string(SPHCAST_SOURCE_ETC_DIR)), std::string::npos) << message;
}

TEST(Dictionary, IncludeCycleIsAnError) {
  EXPECT_EQ(
      errorOf([] { Dictionary::read(dataDir + "/cycleA"); }),
      dataDir + "/cycleB:2:1: #include cycle: '" + dataDir + "/cycleA' is already being read");
}

TEST(Dictionary, IncludeDeeperThan32FilesIsAnError) {
  const fs::path folder = fs::temp_directory_path() / "sphCastDictionaryIncludeDepth";
  fs::create_directories(folder);
  for (int level = 0; level < 40; ++level) {
    std::ofstream(folder / ("level" + std::to_string(level)))
        << "key" << level << " " << level << ";\n#include \"level" << level + 1 << "\"\n";
  }
  const std::string message = errorOf([&] { Dictionary::read(folder / "level0"); });
  EXPECT_EQ(message, (folder / "level32").string() + ":2:1: #include nested deeper than 32 files");
  fs::remove_all(folder);
}

TEST(Dictionary, MissingFileIsAnErrorNamingIt) {
  EXPECT_EQ(errorOf([] { Dictionary::read("/no/such/case/system/controlDict"); }),
            "/no/such/case/system/controlDict: cannot open file");
  EXPECT_EQ(errorOf([] { Dictionary::read(dataDir); }), dataDir + ": cannot open file");
}

// ---------------------------------------------------------------------------------------------
// Accessors with defaults, choices and key checks

TEST(Dictionary, GetOrDefaultFallsBackOnlyWhenTheKeyIsMissing) {
  const Dictionary dict = parse("maxCo 0.5;");
  EXPECT_EQ(dict.getOrDefault<double>("maxCo", 0.2), 0.5);
  EXPECT_EQ(dict.getOrDefault<double>("maxDeltaT", 1.0), 1.0);
  EXPECT_EQ(dict.getOrDefault<std::string>("name", "none"), "none");
  EXPECT_EQ(errorOf([&] { dict.getOrDefault<int>("maxCo", 1); }),
            "controlDict:1:7: expected an integer for 'maxCo', found number 0.5");
}

TEST(Dictionary, GetChoiceAcceptsOnlyTheListedWords) {
  const Dictionary dict = parse("stopAt writeNow; bad foo; quoted \"endTime\";");
  const std::vector<std::string> stopAt{"endTime", "writeNow", "noWriteNow"};
  EXPECT_EQ(dict.getChoice("stopAt", stopAt), "writeNow");
  EXPECT_EQ(dict.getChoice("quoted", stopAt), "endTime");
  EXPECT_EQ(dict.getChoiceOrDefault("missing", stopAt, "endTime"), "endTime");
  EXPECT_EQ(dict.getChoiceOrDefault("stopAt", stopAt, "endTime"), "writeNow");
}

TEST(Dictionary, CheckKeysAcceptsValidKeys) {
  const Dictionary dict = parse("FoamFile { object controlDict; } endTime 1; deltaT 0.1;");
  EXPECT_NO_THROW(dict.checkKeys({"startTime", "endTime", "deltaT"}));
}

// ---------------------------------------------------------------------------------------------
// Errors, with the exact message a user sees

TEST(DictionaryError, MisspelledKeySuggestsTheNearestValidKey) {
  const Dictionary dict = parse("startTime 0;\nendTme 1;\n");
  EXPECT_EQ(errorOf([&] {
              dict.checkKeys({"startTime", "endTime", "deltaT"});
            }),
            "controlDict:2:1: unknown key 'endTme' in controlDict; did you mean 'endTime'? "
            "valid keys are: (startTime endTime deltaT)");
}

TEST(DictionaryError, SwappedLettersCountAsOneEditInTheSuggestion) {
  const Dictionary dict = parse("flow\n{\n    modle weaklyCompressible;\n}\n");
  EXPECT_EQ(errorOf([&] {
              dict.subDict("flow").checkKeys({"model", "fluid", "walls"});
            }),
            "controlDict:3:5: unknown key 'modle' in controlDict/flow; did you mean 'model'? "
            "valid keys are: (model fluid walls)");
}

TEST(DictionaryError, UnknownChoiceSuggestsTheNearestValidOne) {
  const Dictionary dict = parse("stopAt wirteNow;");
  EXPECT_EQ(errorOf([&] {
              dict.getChoice("stopAt", {"endTime", "writeNow", "noWriteNow"});
            }),
            "controlDict:1:8: unknown stopAt 'wirteNow'; did you mean 'writeNow'? valid stopAt "
            "are: (endTime writeNow noWriteNow)");
}

TEST(DictionaryError, UnknownKeyWithNothingNearListsTheValidKeys) {
  const Dictionary dict = parse("functions { banana 1; }");
  EXPECT_EQ(errorOf([&] {
              dict.subDict("functions").checkKeys({"probes", "forces"});
            }),
            "controlDict:1:13: unknown key 'banana' in controlDict/functions; valid keys are: "
            "(probes forces)");
}

TEST(DictionaryError, UnknownChoiceListsTheValidOnes) {
  const Dictionary dict = parse("stopAt  foo;\nwriteControl (a b);");
  const std::vector<std::string> stopAt{"endTime", "writeNow", "noWriteNow"};
  EXPECT_EQ(
      errorOf([&] { dict.getChoice("stopAt", stopAt); }),
      "controlDict:1:9: unknown stopAt 'foo'; valid stopAt are: (endTime writeNow noWriteNow)");
  EXPECT_EQ(
      errorOf([&] { dict.getChoiceOrDefault("stopAt", stopAt, "endTime"); }),
      "controlDict:1:9: unknown stopAt 'foo'; valid stopAt are: (endTime writeNow noWriteNow)");
  EXPECT_EQ(errorOf([&] {
              dict.getChoice("writeControl", {"timeStep", "runTime"});
            }),
            "controlDict:2:14: expected one of (timeStep runTime) for 'writeControl', found a list "
            "of 2 items");
}

TEST(DictionaryError, MissingSemicolonBeforeClosingBraceOrEndOfFile) {
  EXPECT_EQ(parseError("a { b 1 }"), "controlDict:1:8: missing ';' after the value of 'b'");
  EXPECT_EQ(parseError("endTime 5\n"),
            "controlDict:1:10: missing ';' after the value of 'endTime'");
  EXPECT_EQ(parseError("endTime"), "controlDict:1:8: missing ';' after the value of 'endTime'");
}

TEST(DictionaryError, MissingSemicolonBetweenLinesIsReportedWhenTheValueIsRead) {
  const Dictionary dict = parse("endTime 5\ndeltaT 0.1;\n");
  EXPECT_EQ(errorOf([&] { dict.get<double>("endTime"); }),
            "controlDict:2:1: unexpected word 'deltaT' after the value of 'endTime'; missing ';' "
            "at the end of line 1?");
  EXPECT_EQ(parseError("endTime 5\nfunctions\n{\n}\n"),
            "controlDict:3:1: unexpected '{' in the value of 'endTime'; missing ';' before it?");
}

TEST(DictionaryError, UnbalancedBracesAndParentheses) {
  EXPECT_EQ(parseError("functions\n{\n    probes { a 1; }\n"),
            "controlDict:2:1: unbalanced '{': missing '}' to close 'functions'");
  EXPECT_EQ(parseError("a 1;\n}\n"), "controlDict:2:1: unbalanced '}': no '{' to close");
  EXPECT_EQ(parseError("points ((0 0 0) (1 1 1);"),
            "controlDict:1:24: missing ')' before ';' in the value of 'points' (the list opened "
            "at line 1, column 8)");
  EXPECT_EQ(parseError("points (1 2"),
            "controlDict:1:8: unbalanced '(' in the value of 'points': missing ')'");
  EXPECT_EQ(parseError("points 1 2);"),
            "controlDict:1:11: unbalanced ')' in the value of 'points'");
  EXPECT_EQ(parseError("a 1;\n)"), "controlDict:2:1: unbalanced ')': no '(' to close");
  EXPECT_EQ(parseError("a { b (1 2 }"),
            "controlDict:1:12: missing ')' before '}' in the value of 'b' (the list opened at "
            "line 1, column 7)");
  EXPECT_EQ(parseError("nu [0 2 -1"),
            "controlDict:1:4: unbalanced '[' in the value of 'nu': missing ']'");
  EXPECT_EQ(parseError("]"), "controlDict:1:1: unbalanced ']': no '[' to close");
  EXPECT_EQ(parseError("(a 1;)"), "controlDict:1:1: expected a key, found '('");
  EXPECT_EQ(parseError("p ({ a 1; });"),
            "controlDict:1:4: sub-dictionaries inside lists are not supported in the value of 'p'");
}

TEST(DictionaryError, WrongDimensionSet) {
  const Dictionary dict = parse("nu [0 1 -1 0 0 0 0] 1e-6;");
  EXPECT_EQ(errorOf([&] { dict.get<double>("nu", kinematicViscosity); }),
            "controlDict:1:4: dimensions [0 1 -1 0 0 0 0] of 'nu' do not match the expected "
            "[0 2 -1 0 0 0 0]");
  EXPECT_EQ(parseError("nu [0 2] 1;"),
            "controlDict:1:4: dimension set of 'nu' has 2 exponents; expected 7: [mass length "
            "time temperature moles current luminous-intensity]");
  EXPECT_EQ(parseError("nu [m^2/s] 1;"),
            "controlDict:1:5: expected a number in the dimension set of 'nu', found word 'm^2/s'");
}

TEST(DictionaryError, WrongTypeNamesTheKeyAndWhatWasFound) {
  const Dictionary dict = parse(
      "g uniform (0 0 -9.81); endTime five; short (0 -9.81); adjust maybe; nx 1.5;\n"
      "table ((300 2700) (900 x)); wide ((1 2 3)); sub { a 1; } name (a b); list 3;");
  EXPECT_EQ(errorOf([&] { dict.get<Vector>("g"); }),
            "controlDict:1:3: expected a vector (x y z) for 'g', found word 'uniform'");
  EXPECT_EQ(errorOf([&] { dict.get<double>("endTime"); }),
            "controlDict:1:32: expected a number for 'endTime', found word 'five'");
  EXPECT_EQ(errorOf([&] { dict.get<Vector>("short"); }),
            "controlDict:1:44: expected a vector (x y z) for 'short', found a list of 2 items");
  EXPECT_EQ(errorOf([&] { dict.get<bool>("adjust"); }),
            "controlDict:1:62: expected a boolean (yes/no/on/off/true/false) for 'adjust', found "
            "word 'maybe'");
  EXPECT_EQ(errorOf([&] { dict.get<int>("nx"); }),
            "controlDict:1:72: expected an integer for 'nx', found number 1.5");
  using Row = std::tuple<double, double>;
  EXPECT_EQ(errorOf([&] { dict.get<std::vector<Row>>("table"); }),
            "controlDict:2:24: expected a number for 'table' item 2.2, found word 'x'");
  EXPECT_EQ(errorOf([&] { dict.get<std::vector<Row>>("wide"); }),
            "controlDict:2:35: expected a list of 2 values for 'wide' item 1, found a list of 3 "
            "items");
  EXPECT_EQ(errorOf([&] { dict.get<double>("sub"); }),
            "controlDict:2:45: expected a number for 'sub', found a sub-dictionary");
  EXPECT_EQ(errorOf([&] { dict.get<std::string>("name"); }),
            "controlDict:2:63: expected a word or string for 'name', found a list of 2 items");
  EXPECT_EQ(errorOf([&] { dict.get<std::vector<int>>("list"); }),
            "controlDict:2:75: expected a list for 'list', found number 3");
  EXPECT_EQ(errorOf([&] { dict.subDict("g"); }),
            "controlDict:1:1: expected a sub-dictionary { ... } for 'g' in controlDict, found a "
            "value");
}

TEST(DictionaryError, IntegerOutOfRange) {
  const Dictionary dict = parse("nx 3000000000; n -1; huge 1e300;");
  EXPECT_EQ(
      errorOf([&] { dict.get<int>("nx"); }),
      "controlDict:1:4: number 3000000000 for 'nx' is out of range [-2147483648, 2147483647]");
  EXPECT_EQ(errorOf([&] { dict.get<std::size_t>("n"); }),
            "controlDict:1:18: number -1 for 'n' is out of range [0, 9223372036854775807]");
  EXPECT_EQ(errorOf([&] { dict.get<long long>("huge"); }),
            "controlDict:1:27: number 1e300 for 'huge' is out of range [-9223372036854775808, "
            "9223372036854775807]");
  EXPECT_EQ(errorOf([&] { dict.get<float>("huge"); }),
            "controlDict:1:27: number 1e300 for 'huge' is out of range for single precision");
}

TEST(DictionaryError, MissingKeyNamesTheDictionary) {
  const Dictionary dict = parse("a 1;\nfunctions\n{\n}\n");
  EXPECT_EQ(errorOf([&] { dict.get<double>("endTime"); }),
            "controlDict:1:1: missing key 'endTime' in controlDict");
  EXPECT_EQ(errorOf([&] { dict.subDict("functions").get<int>("x"); }),
            "controlDict:2:1: missing key 'x' in controlDict/functions");
  EXPECT_EQ(errorOf([&] { dict.subDict("solver"); }),
            "controlDict:1:1: missing sub-dictionary 'solver' in controlDict");
  EXPECT_EQ(errorOf([&] { dict.location("x"); }),
            "controlDict:1:1: missing key 'x' in controlDict");
}

TEST(DictionaryError, CountMismatchInCountedList) {
  EXPECT_EQ(parseError("p 3(1 2);"),
            "controlDict:1:3: list for 'p' has 2 items but its count says 3");
  const Dictionary spaced = parse("p 3 (1 2);");
  EXPECT_EQ(errorOf([&] { spaced.get<std::vector<double>>("p"); }),
            "controlDict:1:3: list for 'p' has 2 items but its count says 3");
}

TEST(DictionaryError, UndefinedMacro) {
  EXPECT_EQ(parseError("a $b;"), "controlDict:1:3: undefined macro '$b' in the value of 'a'");
  EXPECT_EQ(parseError("a { x 1; }\n$b"), "controlDict:2:1: undefined macro '$b'");
  EXPECT_EQ(parseError("a { x 1; } b $a.y;"),
            "controlDict:1:14: undefined macro '$a.y' in the value of 'b'");
  EXPECT_EQ(parseError("a 1; b { c $...a; }"),
            "controlDict:1:12: undefined macro '$...a' in the value of 'c'");
  EXPECT_EQ(parseError("a 1;\n$a"),
            "controlDict:2:1: macro '$a' on its own must name a sub-dictionary to merge here; "
            "found a value");
  EXPECT_EQ(parseError("d { x 1; } l (1 $d);"),
            "controlDict:1:17: macro '$d' names a sub-dictionary, which cannot be part of a value "
            "or list in the value of 'l'");
  EXPECT_EQ(parseError("a $"), "controlDict:1:3: expected a macro name after '$'");
}

TEST(DictionaryError, UnterminatedCommentOrString) {
  EXPECT_EQ(parseError("a 1; /* open"), "controlDict:1:6: unterminated comment: '/*' without '*/'");
  EXPECT_EQ(parseError("a \"abc;"), "controlDict:1:3: unterminated string: missing closing '\"'");
}

TEST(DictionaryError, BadOrOutOfRangeNumber) {
  EXPECT_EQ(parseError("a 1.2.3;"), "controlDict:1:3: bad number '1.2.3'");
  EXPECT_EQ(parseError("a 0x1F;"), "controlDict:1:3: bad number '0x1F'");
  EXPECT_EQ(parseError("a 12abc;"), "controlDict:1:3: bad number '12abc'");
}

TEST(DictionaryError, NumberBeyondTheLargestDoubleNamesItsKey) {
  const std::string beyond = " is out of range: its magnitude exceeds the largest double, 1.8e308";
  EXPECT_EQ(parseError("a 1e999;"), "controlDict:1:3: number 1e999 for 'a'" + beyond);
  EXPECT_EQ(parseError("b 1;\ng (0 0 -1e999);"), "controlDict:2:8: number -1e999 for 'g'" + beyond);
  EXPECT_EQ(parseError("nu [0 2e999 -1 0 0 0 0] 1;"),
            "controlDict:1:7: number 2e999 for 'nu'" + beyond);
  EXPECT_EQ(parseError("sub { deep { x 1e400; } }"),
            "controlDict:1:16: number 1e400 for 'x'" + beyond);
}

TEST(DictionaryError, UnsupportedDirectives) {
  EXPECT_EQ(parseError("#inputMode merge"), "controlDict:1:1: unsupported directive '#inputMode'");
  EXPECT_EQ(parseError("a #calc \"1+2\";"),
            "controlDict:1:3: unsupported directive '#calc' in the value of 'a'");
  EXPECT_EQ(parseError("code #{ int x; #};"),
            "controlDict:1:6: unsupported directive '#{' in the value of 'code'");
  EXPECT_EQ(parseError("#include (a)"),
            "controlDict:1:10: expected a file name after #include, found '('");
  EXPECT_EQ(parseError("# x"), "controlDict:1:1: expected a directive name after '#'");
  EXPECT_EQ(parseError("a 3{0};"),
            "controlDict:1:3: uniform lists N{value} are not supported (in the value of 'a')");
}

// ---------------------------------------------------------------------------------------------
// Robustness against arbitrary bytes

TEST(DictionaryRobustness, NulAndNonAsciiBytesOutsideStringsAreErrors) {
  EXPECT_EQ(parseError(std::string("a \0;", 4)),
            "controlDict:1:3: invalid byte 0x00 outside a string or comment");
  EXPECT_EQ(parseError("a \xC3\xA9;"),
            "controlDict:1:3: invalid byte 0xC3 outside a string or comment");
  EXPECT_EQ(parseError("a\x01"), "controlDict:1:2: invalid byte 0x01 outside a string or comment");
}

TEST(DictionaryRobustness, ArbitraryBytesInsideStringsAndCommentsAreKept) {
  const char text[] = "// caf\xC3\xA9 \xFF\n a \"x\0y\xFE\"; /* \x80 */";
  const Dictionary dict = parse(std::string_view(text, sizeof(text) - 1));
  EXPECT_EQ(dict.get<std::string>("a"), std::string("x\0y\xFE", 4));
}

TEST(DictionaryRobustness, NestingDeeperThan256LevelsIsAnError) {
  EXPECT_EQ(parseError("a " + std::string(300, '(')),
            "controlDict:1:259: nesting deeper than 256 levels");
  std::string braces;
  for (int i = 0; i < 300; ++i) braces += "a{";
  EXPECT_EQ(parseError(braces), "controlDict:1:514: nesting deeper than 256 levels");
  std::string deepList = "a " + std::string(256, '(') + std::string(256, ')') + ";";
  EXPECT_NO_THROW(parse(deepList));
}

TEST(DictionaryRobustness, MacrosCannotBuildNestingBeyondTheLimit) {
  // Each line nests the previous value one level deeper; copies must respect the limit too.
  std::string text = "a0 " + std::string(200, '(') + std::string(200, ')') + ";\n";
  for (int i = 1; i < 5; ++i) {
    text += "a" + std::to_string(i) + " " + std::string(40, '(') + "$a" + std::to_string(i - 1) +
            std::string(40, ')') + ";\n";
  }
  EXPECT_EQ(parseError(text), "controlDict:3:44: nesting deeper than 256 levels");
}

TEST(DictionaryRobustness, ExponentialMacroExpansionIsStopped) {
  std::string text = "a0 (1 2 3 4 5 6 7 8);\n";
  for (int i = 1; i < 40; ++i) {
    text += "a" + std::to_string(i) + " ($a" + std::to_string(i - 1) + " $a" +
            std::to_string(i - 1) + ");\n";
  }
  const std::string message = parseError(text);
  EXPECT_NE(message.find("macro expansion too large: more than 250000 items copied"),
            std::string::npos)
      << message;
}

TEST(Dictionary, ChecksADimensionsEntryAsConstantGWritesIt) {
  const Dictionary g = parse("dimensions [0 1 -2 0 0 0 0];\nvalue (0 0 -9.81);\nwrong 3;\n");
  EXPECT_NO_THROW(g.checkDimensions("dimensions", acceleration));
  EXPECT_EQ(errorOf([&] { g.checkDimensions("dimensions", kinematicViscosity); }),
            "controlDict:1:12: dimensions [0 1 -2 0 0 0 0] of 'dimensions' do not match the "
            "expected [0 2 -1 0 0 0 0]");
  EXPECT_EQ(errorOf([&] { g.checkDimensions("wrong", acceleration); }),
            "controlDict:3:1: expected a dimension set [0 1 -2 0 0 0 0] for 'wrong'");
}

}  // namespace
}  // namespace sphcast
