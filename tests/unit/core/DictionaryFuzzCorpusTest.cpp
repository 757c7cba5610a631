#include <gtest/gtest.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/Real.h"
#include "core/dictionary/Dictionary.h"

namespace sphcast {
namespace {

namespace fs = std::filesystem;

// Replays the fuzzer's corpus (tests/fuzz/corpus/dictionary) in the normal build: every input,
// valid or broken, must either parse or throw a DictionaryError; nothing else may escape.
TEST(DictionaryFuzzCorpus, EveryInputParsesOrThrowsDictionaryError) {
  const fs::path corpus = fs::path(SPHCAST_FUZZ_CORPUS_DIR) / "dictionary";
  ASSERT_TRUE(fs::is_directory(corpus)) << corpus;
  int inputs = 0;
  for (const fs::directory_entry& file : fs::directory_iterator(corpus)) {
    if (!file.is_regular_file()) continue;
    std::ifstream stream(file.path(), std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(stream),
                           std::istreambuf_iterator<char>()};
    ++inputs;
    try {
      // Named inside the corpus folder, as the fuzzer does, so relative #includes stay there.
      const Dictionary dict = Dictionary::parse(text, (corpus / "input").string());
      for (const std::string& key : dict.keys()) {
        try {
          (void)dict.get<double>(key);
        } catch (const DictionaryError&) {
        }
        try {
          (void)dict.get<std::vector<Vector>>(key);
        } catch (const DictionaryError&) {
        }
      }
    } catch (const DictionaryError&) {
    } catch (const std::exception& error) {
      ADD_FAILURE() << file.path()
                    << " threw something other than a DictionaryError: " << error.what();
    }
  }
  EXPECT_GT(inputs, 0);
}

}  // namespace
}  // namespace sphcast
