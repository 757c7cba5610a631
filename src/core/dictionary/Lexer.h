#pragma once

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "core/dictionary/ValueItem.h"

namespace sphcast::dictionary {

struct Token {
  enum class Kind {
    Word,         // endTime, div(phi,U), uniform, FoamFile
    String,       // "quoted", escapes resolved
    Number,       // 1, -2.5e3
    Punctuation,  // one of { } ( ) [ ] ;
    Directive,    // #include, #calc, ... (text keeps the '#')
    Macro,        // $name, ${name}, $sub.key, $:top.key (text without the '$' and braces)
    EndOfFile
  };

  Kind kind = Kind::EndOfFile;
  std::string text;
  double number = 0.0;
  bool isInteger = false;
  // Beyond the largest double (1e999): an error where the parser knows whose value it is.
  bool outOfRange = false;
  char punctuation = '\0';
  TextPosition position;  // first byte
  int endLine = 0;        // just after the last byte, for "missing ';' after ..."
  int endColumn = 0;
  bool afterSpace = false;  // whitespace or a comment separates it from the previous token

  bool is(char mark) const { return kind == Kind::Punctuation && punctuation == mark; }
};

// Splits OpenFOAM dictionary text into tokens, one at a time, skipping // and /* */ comments.
// Any byte sequence is accepted as input: what is not valid syntax becomes a DictionaryError
// with its line and column.
class Lexer {
 public:
  Lexer(std::string_view text, std::string fileName);

  const Token& peek();
  Token next();
  const std::shared_ptr<const std::string>& fileName() const { return fileName_; }
  // Just after the last token that next() returned (the start of the text before any).
  SourceLocation previousEnd() const {
    return SourceLocation{*fileName_, previousEndLine_, previousEndColumn_};
  }

 private:
  Token scan();
  bool skipSpaceAndComments();  // true if anything was skipped
  void advance();               // one byte, keeping line and column
  char current() const { return text_[offset_]; }
  bool atEnd() const { return offset_ >= text_.size(); }
  char lookAhead(std::size_t distance) const;
  TextPosition here() const { return TextPosition{fileName_, line_, column_}; }
  [[noreturn]] void fail(const TextPosition& where, const std::string& message) const;

  void scanString(Token& token);
  void scanWordOrNumber(Token& token);
  void scanMacro(Token& token);
  std::size_t wordRunEnd(std::size_t from) const;
  std::size_t balancedParenthesesEnd(std::size_t from) const;

  std::string_view text_;
  std::shared_ptr<const std::string> fileName_;
  std::size_t offset_ = 0;
  int line_ = 1;
  int column_ = 1;
  std::optional<Token> lookahead_;
  int previousEndLine_ = 1;
  int previousEndColumn_ = 1;
};

}  // namespace sphcast::dictionary
