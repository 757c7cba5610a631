#include "core/dictionary/Parser.h"

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <system_error>

namespace sphcast::dictionary {

namespace fs = std::filesystem;

namespace {

SourceLocation locationOf(const Token& token) { return token.position.location(); }

std::string inQuotes(std::string_view key) {
  // Appended piecewise: "'" + std::string(...) trips a false -Wrestrict in GCC 12.
  std::string text(1, '\'');
  text.append(key);
  text += '\'';
  return text;
}

std::string describe(const Token& token) {
  switch (token.kind) {
    case Token::Kind::Word:
      return "word '" + token.text + "'";
    case Token::Kind::String:
      return "string \"" + token.text + "\"";
    case Token::Kind::Number:
      return "number " + token.text;
    case Token::Kind::Punctuation:
      return "'" + token.text + "'";
    case Token::Kind::Directive:
      return "directive '" + token.text + "'";
    case Token::Kind::Macro:
      return "macro '$" + token.text + "'";
    case Token::Kind::EndOfFile:
      return "the end of the file";
  }
  return "a token";
}

void checkNesting(int depth, const Token& where) {
  if (depth > Parser::maxNesting) {
    throw DictionaryError(locationOf(where),
                          "nesting deeper than " + std::to_string(Parser::maxNesting) + " levels");
  }
}

// A number beyond the largest double is named with the key whose value holds it.
void checkInRange(const Token& number, const std::string& key) {
  if (number.outOfRange) {
    throw DictionaryError(locationOf(number), "number " + number.text + " for " + inQuotes(key) +
                                                  " is out of range: its magnitude exceeds the "
                                                  "largest double, 1.8e308");
  }
}

// `3(a b c)`: an unsigned integer written right against '(' counts the list that follows.
bool isListCount(const Token& number, const Token& following) {
  return number.kind == Token::Kind::Number && number.isInteger && number.text.front() != '-' &&
         number.text.front() != '+' && following.is('(') && !following.afterSpace;
}

ValueItem itemFrom(const Token& token) {
  ValueItem item;
  item.kind = token.kind == Token::Kind::Number   ? ValueItem::Kind::Number
              : token.kind == Token::Kind::String ? ValueItem::Kind::String
                                                  : ValueItem::Kind::Word;
  item.text = token.text;
  item.number = token.number;
  item.isInteger = token.isInteger;
  item.position = token.position;
  return item;
}

std::string readWholeFile(const fs::path& path, const SourceLocation& where,
                          const std::string& what) {
  std::error_code error;
  // Only regular files: a device such as /dev/zero would never end.
  const bool regular = !path.native().empty() && path.native().find('\0') == std::string::npos &&
                       fs::is_regular_file(path, error);
  if (!regular) throw DictionaryError(where, "cannot open " + what);
  const std::uintmax_t size = fs::file_size(path, error);
  if (error) throw DictionaryError(where, "cannot open " + what);
  if (size > Parser::maxFileBytes) {
    throw DictionaryError(
        where, what + " is larger than " + std::to_string(Parser::maxFileBytes >> 20) + " MiB");
  }
  std::ifstream stream(path, std::ios::binary);
  if (!stream) throw DictionaryError(where, "cannot open " + what);
  std::string text(static_cast<std::size_t>(size), '\0');
  stream.read(text.data(), static_cast<std::streamsize>(size));
  if (stream.bad()) throw DictionaryError(where, "cannot read " + what);
  text.resize(static_cast<std::size_t>(stream.gcount()));
  return text;
}

fs::path identityOf(const fs::path& path) {
  std::error_code error;
  fs::path canonical = fs::weakly_canonical(path, error);
  return error ? path.lexically_normal() : canonical;
}

}  // namespace

Dictionary Parser::parseText(std::string_view text, const std::string& fileName) {
  Parser parser;
  Dictionary top;
  top.name_ = fs::path(fileName).stem().string();
  top.location_ = SourceLocation{fileName, 1, 1};
  parser.scopes_.push_back(&top);
  parser.includeStack_.push_back(identityOf(fileName));
  Lexer lexer(text, fileName);
  parser.parseEntries(lexer, top, 0, nullptr, "");
  return top;
}

Dictionary Parser::readFile(const fs::path& file) {
  const std::string text = readWholeFile(file, SourceLocation{file.string(), 0, 0}, "file");
  return parseText(text, file.string());
}

void Parser::parseEntries(Lexer& lexer, Dictionary& scope, int depth, const Token* openingBrace,
                          const std::string& scopeKey) {
  for (;;) {
    const Token& token = lexer.peek();
    switch (token.kind) {
      case Token::Kind::EndOfFile:
        if (openingBrace) {
          throw DictionaryError(locationOf(*openingBrace),
                                "unbalanced '{': missing '}' to close " + inQuotes(scopeKey));
        }
        return;
      case Token::Kind::Directive:
        parseDirective(lexer, scope, depth);
        break;
      case Token::Kind::Macro:
        mergeMacroDictionary(lexer, scope, depth);
        break;
      case Token::Kind::Word:
      case Token::Kind::String:
      case Token::Kind::Number: {
        const Token key = lexer.next();
        parseEntry(lexer, scope, key, depth);
        break;
      }
      case Token::Kind::Punctuation:
        if (token.is(';')) {  // a stray ';' ends nothing, and harms nothing
          lexer.next();
        } else if (token.is('}')) {
          if (!openingBrace)
            throw DictionaryError(locationOf(token), "unbalanced '}': no '{' to close");
          lexer.next();
          return;
        } else if (token.is(')')) {
          throw DictionaryError(locationOf(token), "unbalanced ')': no '(' to close");
        } else if (token.is(']')) {
          throw DictionaryError(locationOf(token), "unbalanced ']': no '[' to close");
        } else {
          throw DictionaryError(locationOf(token), "expected a key, found " + describe(token));
        }
        break;
    }
  }
}

void Parser::parseEntry(Lexer& lexer, Dictionary& scope, const Token& key, int depth) {
  Entry entry;
  entry.key = key.text;
  entry.where = locationOf(key);
  if (lexer.peek().is('{')) {
    const Token brace = lexer.next();
    checkNesting(depth + 1, brace);
    auto child = std::make_shared<Dictionary>();
    child->name_ = scope.name_ + "/" + entry.key;
    child->location_ = entry.where;
    scopes_.push_back(child.get());
    parseEntries(lexer, *child, depth + 1, &brace, entry.key);
    scopes_.pop_back();
    entry.subDict = std::move(child);
  } else {
    parseValue(lexer, entry, depth);
  }

  const bool isHeader = &scope == scopes_.front() && entry.key == "FoamFile" && entry.subDict;
  if (isHeader) {
    // The main file's header comes first; those of included files say nothing new.
    if (!scope.header_) scope.header_ = std::move(entry.subDict);
    return;
  }
  insertEntry(scope, std::move(entry));
}

void Parser::parseValue(Lexer& lexer, Entry& entry, int depth) {
  const std::string inValue = " in the value of " + inQuotes(entry.key);
  entry.valueEnd = lexer.previousEnd();
  for (;;) {
    const Token token = lexer.next();
    if (token.is(';')) return;
    if (token.kind == Token::Kind::EndOfFile || token.is('}')) {
      throw DictionaryError(entry.valueEnd,
                            "missing ';' after the value of " + inQuotes(entry.key));
    }
    // `key $dict;` makes key a copy of the sub-dictionary dict.
    if (token.kind == Token::Kind::Macro && entry.value.empty()) {
      const Entry* source = resolveMacro(token, inValue);
      if (source->subDict && lexer.peek().is(';')) {
        lexer.next();
        checkNesting(depth + 1, token);
        entry.subDict = cloneDictionary(*source->subDict, scopes_.back()->name_ + "/" + entry.key,
                                        entry.where, depth + 1, token);
        return;
      }
    }
    if (!parseItem(lexer, token, entry.value, entry.key, depth)) {
      if (token.is('{')) {
        throw DictionaryError(locationOf(token),
                              "unexpected '{'" + inValue + "; missing ';' before it?");
      }
      if (token.is(')') || token.is(']')) {
        throw DictionaryError(locationOf(token), "unbalanced '" + token.text + "'" + inValue);
      }
      throw DictionaryError(locationOf(token),
                            "unsupported directive '" + token.text + "'" + inValue);
    }
    entry.valueEnd = lexer.previousEnd();
  }
}

bool Parser::parseItem(Lexer& lexer, const Token& token, std::vector<ValueItem>& items,
                       const std::string& key, int depth) {
  switch (token.kind) {
    case Token::Kind::Number:
      checkInRange(token, key);
      if (token.isInteger && lexer.peek().is('{') && !lexer.peek().afterSpace) {
        throw DictionaryError(
            locationOf(token),
            "uniform lists N{value} are not supported (in the value of " + inQuotes(key) + ")");
      }
      if (isListCount(token, lexer.peek())) {
        const Token opening = lexer.next();
        ValueItem list = parseList(lexer, opening, key, depth);
        unsigned long long declared = 0;
        const char* end = token.text.data() + token.text.size();
        const auto [stop, error] = std::from_chars(token.text.data(), end, declared);
        if (error != std::errc() || stop != end || declared != list.items.size()) {
          throw DictionaryError(locationOf(token),
                                countMismatchMessage(inQuotes(key), token.text, list.items.size()));
        }
        items.push_back(std::move(list));
      } else {
        items.push_back(itemFrom(token));
      }
      return true;
    case Token::Kind::Word:
    case Token::Kind::String:
      items.push_back(itemFrom(token));
      return true;
    case Token::Kind::Macro: {
      const std::string inValue = " in the value of " + inQuotes(key);
      const Entry* source = resolveMacro(token, inValue);
      if (source->subDict) {
        throw DictionaryError(locationOf(token), "macro '$" + token.text +
                                                     "' names a sub-dictionary, which cannot be "
                                                     "part of a value or list" +
                                                     inValue);
      }
      // Copy before appending: the source may be an earlier part of this very value's scope,
      // but never `items` itself, which is not yet an entry.
      for (const ValueItem& item : source->value) items.push_back(copyItem(item, depth, token));
      return true;
    }
    case Token::Kind::Punctuation:
      if (token.is('(')) {
        items.push_back(parseList(lexer, token, key, depth));
        return true;
      }
      if (token.is('[')) {
        items.push_back(parseDimensions(lexer, token, key));
        return true;
      }
      return false;
    case Token::Kind::Directive:
    case Token::Kind::EndOfFile:
      return false;
  }
  return false;
}

ValueItem Parser::parseList(Lexer& lexer, const Token& opening, const std::string& key, int depth) {
  checkNesting(depth + 1, opening);
  const std::string inValue = " in the value of " + inQuotes(key);
  ValueItem list;
  list.kind = ValueItem::Kind::List;
  list.position = opening.position;
  for (;;) {
    const Token token = lexer.next();
    if (token.is(')')) return list;
    if (parseItem(lexer, token, list.items, key, depth + 1)) continue;
    if (token.kind == Token::Kind::EndOfFile) {
      throw DictionaryError(locationOf(opening), "unbalanced '('" + inValue + ": missing ')'");
    }
    if (token.is(';') || token.is('}')) {
      throw DictionaryError(locationOf(token), "missing ')' before '" + token.text + "'" + inValue +
                                                   " (the list opened at line " +
                                                   std::to_string(opening.position.line) +
                                                   ", column " +
                                                   std::to_string(opening.position.column) + ")");
    }
    if (token.is('{')) {
      throw DictionaryError(locationOf(token),
                            "sub-dictionaries inside lists are not supported" + inValue);
    }
    if (token.is(']')) {
      throw DictionaryError(locationOf(token), "unbalanced ']'" + inValue);
    }
    throw DictionaryError(locationOf(token),
                          "unsupported directive '" + token.text + "'" + inValue);
  }
}

ValueItem Parser::parseDimensions(Lexer& lexer, const Token& opening, const std::string& key) {
  ValueItem dimensions;
  dimensions.kind = ValueItem::Kind::Dimensions;
  dimensions.position = opening.position;
  for (;;) {
    const Token token = lexer.next();
    if (token.is(']')) break;
    if (token.kind == Token::Kind::EndOfFile) {
      throw DictionaryError(locationOf(opening),
                            "unbalanced '[' in the value of " + inQuotes(key) + ": missing ']'");
    }
    if (token.kind != Token::Kind::Number) {
      throw DictionaryError(locationOf(token), "expected a number in the dimension set of " +
                                                   inQuotes(key) + ", found " + describe(token));
    }
    checkInRange(token, key);
    dimensions.items.push_back(itemFrom(token));
  }
  const std::size_t count = dimensions.items.size();
  // OpenFOAM also accepts the first five (mass length time temperature moles).
  if (count != 7 && count != 5) {
    throw DictionaryError(locationOf(opening),
                          "dimension set of " + inQuotes(key) + " has " + std::to_string(count) +
                              " exponents; expected 7: [mass length time temperature moles "
                              "current luminous-intensity]");
  }
  return dimensions;
}

std::vector<fs::path> Parser::etcFolders() {
  std::vector<fs::path> folders;
  if (const char* variable = std::getenv("SPHCAST_ETC"); variable && *variable) {
    folders.emplace_back(variable);
  }
#ifdef SPHCAST_ETC_DIR
  folders.emplace_back(SPHCAST_ETC_DIR);
#endif
  // An install puts the executables in <repo>/platforms/bin.
  std::error_code error;
  const fs::path executable = fs::read_symlink("/proc/self/exe", error);
  if (!error) folders.push_back((executable.parent_path() / "../../etc").lexically_normal());
  return folders;
}

void Parser::parseDirective(Lexer& lexer, Dictionary& scope, int depth) {
  const Token directive = lexer.next();
  const bool optional = directive.text == "#includeIfPresent";
  const bool etc = directive.text == "#includeEtc";
  if (directive.text != "#include" && !optional && !etc) {
    throw DictionaryError(locationOf(directive), "unsupported directive '" + directive.text + "'");
  }
  const Token fileToken = lexer.next();
  if (fileToken.kind != Token::Kind::String && fileToken.kind != Token::Kind::Word) {
    throw DictionaryError(locationOf(fileToken), "expected a file name after " + directive.text +
                                                     ", found " + describe(fileToken));
  }
  fs::path path = fs::path(*lexer.fileName()).parent_path() / fileToken.text;
  if (etc) {
    // As OpenFOAM's #includeEtc: the first of the etc folders that holds the file.
    const std::vector<fs::path> folders = etcFolders();
    const auto holder = std::find_if(folders.begin(), folders.end(), [&](const fs::path& folder) {
      std::error_code error;
      return fs::is_regular_file(folder / fileToken.text, error);
    });
    if (holder == folders.end()) {
      std::string searched;
      for (const fs::path& folder : folders) searched += " " + folder.string();
      throw DictionaryError(locationOf(directive),
                            "#includeEtc file '" + fileToken.text +
                                "' is in none of the sphCast etc folders ($SPHCAST_ETC, the "
                                "source tree's etc/, ../../etc of the executable); searched (" +
                                searched + " )");
    }
    path = *holder / fileToken.text;
  }
  const std::string what = directive.text + " file '" + path.string() + "'";

  const fs::path identity = identityOf(path);
  for (const fs::path& open : includeStack_) {
    if (open == identity) {
      throw DictionaryError(locationOf(directive),
                            "#include cycle: '" + path.string() + "' is already being read");
    }
  }
  if (includeStack_.size() > maxIncludeDepth) {
    throw DictionaryError(locationOf(directive), "#include nested deeper than " +
                                                     std::to_string(maxIncludeDepth) + " files");
  }
  std::string text;
  try {
    text = readWholeFile(path, locationOf(directive), what);
  } catch (const DictionaryError&) {
    std::error_code error;
    if (optional && !fs::exists(path, error)) return;
    throw;
  }
  includeStack_.push_back(identity);
  Lexer included(text, path.string());
  parseEntries(included, scope, depth, nullptr, "");
  includeStack_.pop_back();
}

void Parser::mergeMacroDictionary(Lexer& lexer, Dictionary& scope, int depth) {
  const Token macro = lexer.next();
  const Entry* source = resolveMacro(macro, "");
  if (!source->subDict) {
    throw DictionaryError(locationOf(macro), "macro '$" + macro.text +
                                                 "' on its own must name a sub-dictionary to "
                                                 "merge here; found a value");
  }
  // Clone first: the source may live in `scope`, whose entries the merge is about to change.
  const std::shared_ptr<Dictionary> copy =
      cloneDictionary(*source->subDict, scope.name_, scope.location_, depth, macro);
  for (Entry& entry : copy->entries_) insertEntry(scope, std::move(entry));
}

const Dictionary::Entry* Parser::resolveMacro(const Token& macro,
                                              const std::string& context) const {
  std::string_view path = macro.text;
  std::vector<const Dictionary*> searched;
  if (path.front() == ':') {  // $:top.key
    path.remove_prefix(1);
    searched.push_back(scopes_.front());
  } else if (path.front() == '.') {  // $.key here, $..key one scope up
    std::size_t dots = 0;
    while (dots < path.size() && path[dots] == '.') ++dots;
    path.remove_prefix(dots);
    if (dots <= scopes_.size()) searched.push_back(scopes_[scopes_.size() - dots]);
  } else {  // innermost scope first, then outwards
    for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope)
      searched.push_back(*scope);
  }

  for (const Dictionary* scope : searched) {
    std::string_view rest = path;
    const Dictionary* current = scope;
    while (current && !rest.empty()) {
      // A key may itself hold dots, so try the whole rest before splitting off a scope.
      if (const Entry* entry = current->findEntry(rest)) return entry;
      const std::size_t separator = rest.find_first_of("./");
      if (separator == std::string_view::npos) break;
      const Entry* parent = current->findEntry(rest.substr(0, separator));
      current = parent ? parent->subDict.get() : nullptr;
      rest.remove_prefix(separator + 1);
    }
  }
  throw DictionaryError(locationOf(macro), "undefined macro '$" + macro.text + "'" + context);
}

void Parser::chargeCopy(const Token& macro) {
  if (++copiedItems_ > maxCopiedItems) {
    throw DictionaryError(locationOf(macro), "macro expansion too large: more than " +
                                                 std::to_string(maxCopiedItems) + " items copied");
  }
}

ValueItem Parser::copyItem(const ValueItem& item, int depth, const Token& macro) {
  chargeCopy(macro);
  // Element by element, not `copy = item`: every copy is counted, and the nesting it adds
  // here is bounded.
  ValueItem copy;
  copy.kind = item.kind;
  copy.text = item.text;
  copy.number = item.number;
  copy.isInteger = item.isInteger;
  copy.position = item.position;
  if (item.kind == ValueItem::Kind::List) checkNesting(depth + 1, macro);
  copy.items.reserve(item.items.size());
  for (const ValueItem& element : item.items) {
    copy.items.push_back(copyItem(element, depth + 1, macro));
  }
  return copy;
}

std::shared_ptr<Dictionary> Parser::cloneDictionary(const Dictionary& source,
                                                    const std::string& name,
                                                    const SourceLocation& where, int depth,
                                                    const Token& macro) {
  auto copy = std::make_shared<Dictionary>();
  copy->name_ = name;
  copy->location_ = where;
  for (const Entry& entry : source.entries_) {
    chargeCopy(macro);
    Entry cloned;
    cloned.key = entry.key;
    cloned.where = entry.where;
    cloned.copied = true;
    cloned.valueEnd = entry.valueEnd;
    if (entry.subDict) {
      checkNesting(depth + 1, macro);
      cloned.subDict = cloneDictionary(*entry.subDict, name + "/" + entry.key,
                                       entry.subDict->location_, depth + 1, macro);
    } else {
      for (const ValueItem& item : entry.value)
        cloned.value.push_back(copyItem(item, depth, macro));
    }
    copy->appendEntry(std::move(cloned));
  }
  return copy;
}

void Parser::insertEntry(Dictionary& scope, Entry entry) {
  Entry* existing = scope.findEntry(entry.key);
  if (!existing) {
    scope.appendEntry(std::move(entry));
    return;
  }
  if (existing->subDict && entry.subDict) {
    for (Entry& child : entry.subDict->entries_) insertEntry(*existing->subDict, std::move(child));
    return;
  }
  // The same place read twice is one file included twice, not a key typed twice.
  const bool samePlace =
      existing->where.line == entry.where.line && existing->where.column == entry.where.column;
  if (!existing->copied && !entry.copied && existing->where.file == entry.where.file &&
      !samePlace) {
    throw DictionaryError(entry.where, "duplicate key " + inQuotes(entry.key) + " in " +
                                           scope.name_ + ": given at lines " +
                                           std::to_string(existing->where.line) + " and " +
                                           std::to_string(entry.where.line) +
                                           "; remove one (a key may override only an entry of "
                                           "an #include file or of a $macro merge)");
  }
  *existing = std::move(entry);
}

}  // namespace sphcast::dictionary
