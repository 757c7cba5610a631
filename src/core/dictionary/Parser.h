#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/dictionary/Dictionary.h"
#include "core/dictionary/Lexer.h"

namespace sphcast::dictionary {

// Builds a Dictionary from tokens: entries, sub-dictionaries, lists, dimension sets, and the
// #include (#includeIfPresent, #includeEtc) and $macro substitutions, which are resolved while reading, as OpenFOAM does (a
// macro sees the entries written before it). Input is untrusted: nesting, include depth, file
// size and macro copying are bounded, so no input can exhaust the stack or the memory.
class Parser {
 public:
  static Dictionary parseText(std::string_view text, const std::string& fileName);
  static Dictionary readFile(const std::filesystem::path& file);

  static constexpr int maxNesting = 256;
  static constexpr std::size_t maxIncludeDepth = 32;
  // Copies made by $macro substitution; a few lines of macros can otherwise double a value
  // per line.
  static constexpr std::size_t maxCopiedItems = 250000;
  static constexpr std::uintmax_t maxFileBytes = 64u << 20;

 private:
  using Entry = Dictionary::Entry;

  Parser() = default;

  // Entries up to the end of the text, or up to the '}' matching `openingBrace` when given.
  void parseEntries(Lexer& lexer, Dictionary& scope, int depth, const Token* openingBrace,
                    const std::string& scopeKey);
  void parseEntry(Lexer& lexer, Dictionary& scope, const Token& key, int depth);
  void parseValue(Lexer& lexer, Entry& entry, int depth);
  // #include "file" (relative to the including file's folder), #includeIfPresent "file" (the
  // same, nothing if it is missing) and #includeEtc "file" (in the sphCast etc folders).
  void parseDirective(Lexer& lexer, Dictionary& scope, int depth);
  // Where #includeEtc looks, in order: $SPHCAST_ETC when set, the source tree's etc/ (fixed at
  // build time), and ../../etc of the running executable (an install's <repo>/platforms/bin).
  static std::vector<std::filesystem::path> etcFolders();
  void mergeMacroDictionary(Lexer& lexer, Dictionary& scope, int depth);

  // Appends the item(s) that `token` starts inside a value or list at `depth`; false if the
  // token does not start an item (punctuation, directives), which the caller then handles.
  bool parseItem(Lexer& lexer, const Token& token, std::vector<ValueItem>& items,
                 const std::string& key, int depth);
  ValueItem parseList(Lexer& lexer, const Token& opening, const std::string& key, int depth);
  ValueItem parseDimensions(Lexer& lexer, const Token& opening, const std::string& key);

  const Entry* resolveMacro(const Token& macro, const std::string& context) const;
  ValueItem copyItem(const ValueItem& item, int depth, const Token& macro);
  std::shared_ptr<Dictionary> cloneDictionary(const Dictionary& source, const std::string& name,
                                              const SourceLocation& where, int depth,
                                              const Token& macro);
  void chargeCopy(const Token& macro);

  // Adds or overrides `entry`; a sub-dictionary given again is merged into the earlier one
  // (OpenFOAM's default #inputMode merge), entry by entry. Unlike OpenFOAM, which overrides
  // silently, a value written twice in the same file and scope is an error: only an entry of
  // another file (an #include) or one copied by a $macro merge may be overridden, or override.
  static void insertEntry(Dictionary& scope, Entry entry);

  std::vector<Dictionary*> scopes_;                  // outermost first, for $macro lookup
  std::vector<std::filesystem::path> includeStack_;  // the files being read, outermost first
  std::size_t copiedItems_ = 0;
};

}  // namespace sphcast::dictionary
