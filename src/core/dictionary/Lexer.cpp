#include "core/dictionary/Lexer.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sphcast::dictionary {

namespace {

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

bool isDigit(char c) { return c >= '0' && c <= '9'; }

// OpenFOAM words are printable ASCII up to the characters that structure the file. '/' is
// allowed too, except where it starts a comment (checked by the caller).
bool isWordCharacter(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (byte <= 0x20 || byte >= 0x7f) return false;
  return std::string_view(";{}()[]\"").find(c) == std::string_view::npos;
}

bool startsComment(std::string_view text, std::size_t at) {
  return text[at] == '/' && at + 1 < text.size() && (text[at + 1] == '/' || text[at + 1] == '*');
}

std::string byteName(char c) {
  char buffer[8];
  std::snprintf(buffer, sizeof(buffer), "0x%02X",
                static_cast<unsigned>(static_cast<unsigned char>(c)));
  return buffer;
}

}  // namespace

Lexer::Lexer(std::string_view text, std::string fileName)
    : text_(text), fileName_(std::make_shared<const std::string>(std::move(fileName))) {}

const Token& Lexer::peek() {
  if (!lookahead_) lookahead_ = scan();
  return *lookahead_;
}

Token Lexer::next() {
  Token token = lookahead_ ? std::move(*lookahead_) : scan();
  lookahead_.reset();
  previousEndLine_ = token.endLine;
  previousEndColumn_ = token.endColumn;
  return token;
}

char Lexer::lookAhead(std::size_t distance) const {
  return offset_ + distance < text_.size() ? text_[offset_ + distance] : '\0';
}

void Lexer::advance() {
  if (text_[offset_] == '\n') {
    if (line_ < INT_MAX) ++line_;
    column_ = 1;
  } else if (column_ < INT_MAX) {
    ++column_;
  }
  ++offset_;
}

void Lexer::fail(const TextPosition& where, const std::string& message) const {
  throw DictionaryError(where.location(), message);
}

bool Lexer::skipSpaceAndComments() {
  bool skipped = false;
  while (!atEnd()) {
    if (isSpace(current())) {
      advance();
    } else if (current() == '/' && lookAhead(1) == '/') {
      while (!atEnd() && current() != '\n') advance();
    } else if (current() == '/' && lookAhead(1) == '*') {
      const TextPosition start = here();
      advance();
      advance();
      while (!atEnd() && !(current() == '*' && lookAhead(1) == '/')) advance();
      if (atEnd()) fail(start, "unterminated comment: '/*' without '*/'");
      advance();
      advance();
    } else {
      break;
    }
    skipped = true;
  }
  return skipped;
}

Token Lexer::scan() {
  Token token;
  token.afterSpace = skipSpaceAndComments();
  token.position = here();
  if (atEnd()) {
    token.kind = Token::Kind::EndOfFile;
  } else {
    const char c = current();
    switch (c) {
      case '{':
      case '}':
      case '(':
      case ')':
      case '[':
      case ']':
      case ';':
        token.kind = Token::Kind::Punctuation;
        token.punctuation = c;
        token.text = std::string(1, c);
        advance();
        break;
      case '"':
        scanString(token);
        break;
      case '$':
        scanMacro(token);
        break;
      case '#': {
        token.kind = Token::Kind::Directive;
        advance();
        if (!atEnd() && current() == '{') {  // #{ ... #} verbatim code
          token.text = "#{";
          advance();
          break;
        }
        const std::size_t end = wordRunEnd(offset_);
        if (end == offset_) fail(token.position, "expected a directive name after '#'");
        token.text.push_back('#');
        token.text.append(text_.substr(offset_, end - offset_));
        while (offset_ < end) advance();
        break;
      }
      default:
        if (!isWordCharacter(c)) {
          fail(token.position, "invalid byte " + byteName(c) + " outside a string or comment");
        }
        scanWordOrNumber(token);
    }
  }
  token.endLine = line_;
  token.endColumn = column_;
  return token;
}

std::size_t Lexer::wordRunEnd(std::size_t from) const {
  std::size_t end = from;
  while (end < text_.size() && isWordCharacter(text_[end])) {
    if (startsComment(text_, end)) break;
    ++end;
  }
  return end;
}

// OpenFOAM words may hold balanced parentheses, as in `div(phi,U)`. `from` is the '(' right
// after a word; returns where the word ends: after the last point where the parentheses
// balance, or at `from` if they never do (then `key(1 2 3)` is a word and a list).
std::size_t Lexer::balancedParenthesesEnd(std::size_t from) const {
  // The look-ahead is bounded, or "a(b(c(d(..." would be rescanned from every '(' (quadratic);
  // real words with parentheses are short.
  constexpr std::size_t maxLookAhead = 1024;
  const std::size_t limit = std::min(text_.size(), from + maxLookAhead);
  std::size_t wordEnd = from;
  std::size_t depth = 0;
  for (std::size_t i = from; i < limit; ++i) {
    const char c = text_[i];
    if (c == '(') {
      ++depth;
    } else if (c == ')') {
      if (depth == 0) break;
      --depth;
    } else if (!isWordCharacter(c) || startsComment(text_, i)) {
      break;
    }
    if (depth == 0) wordEnd = i + 1;
  }
  return wordEnd;
}

void Lexer::scanWordOrNumber(Token& token) {
  const std::size_t start = offset_;
  std::size_t end = wordRunEnd(start);
  const std::string_view run = text_.substr(start, end - start);

  // A leading digit, or a sign or point before one, makes it a number (OpenFOAM words cannot
  // start with a digit); "-foo" stays a word.
  const char first = run[0];
  const char second = run.size() > 1 ? run[1] : '\0';
  const char third = run.size() > 2 ? run[2] : '\0';
  const bool signed_ = first == '+' || first == '-';
  const bool looksNumeric = isDigit(first) || ((signed_ || first == '.') && isDigit(second)) ||
                            (signed_ && second == '.' && isDigit(third));

  if (looksNumeric) {
    token.kind = Token::Kind::Number;
    token.text = std::string(run);
    std::string_view digits = run;
    if (first == '+') digits.remove_prefix(1);  // from_chars takes no '+'
    const char* digitsEnd = digits.data() + digits.size();
    const auto [stop, error] = std::from_chars(digits.data(), digitsEnd, token.number);
    if (error == std::errc::result_out_of_range && stop == digitsEnd) {
      // Overflow is an error, reported by the parser with the key; underflow (1e-400) quietly
      // reads as 0 or a subnormal, as in C.
      const std::string copy(digits);
      const double value = std::strtod(copy.c_str(), nullptr);
      token.outOfRange = std::isinf(value) || std::fabs(value) >= 1.0;
      token.number = value;
    } else if (error != std::errc() || stop != digitsEnd) {
      fail(token.position, "bad number '" + token.text + "'");
    }
    token.isInteger = true;
    for (std::size_t i = signed_ ? 1 : 0; i < run.size(); ++i) {
      if (!isDigit(run[i])) token.isInteger = false;
    }
  } else {
    token.kind = Token::Kind::Word;
    if (end < text_.size() && text_[end] == '(') end = balancedParenthesesEnd(end);
    token.text = std::string(text_.substr(start, end - start));
  }
  while (offset_ < end) advance();
}

void Lexer::scanString(Token& token) {
  token.kind = Token::Kind::String;
  advance();  // opening quote
  for (;;) {
    if (atEnd()) fail(token.position, "unterminated string: missing closing '\"'");
    const char c = current();
    if (c == '"') {
      advance();
      return;
    }
    if (c == '\\' && offset_ + 1 < text_.size()) {
      const char escaped = text_[offset_ + 1];
      advance();
      advance();
      switch (escaped) {
        case '"':
          token.text += '"';
          break;
        case '\\':
          token.text += '\\';
          break;
        case 'n':
          token.text += '\n';
          break;
        case 't':
          token.text += '\t';
          break;
        case '\n':
          break;  // a backslash at the end of a line continues the string
        default:  // unknown escapes stay as written, e.g. regular expressions "\d+"
          token.text += '\\';
          token.text += escaped;
      }
      continue;
    }
    token.text += c;
    advance();
  }
}

void Lexer::scanMacro(Token& token) {
  token.kind = Token::Kind::Macro;
  advance();  // '$'
  std::size_t nameStart = offset_;
  std::size_t nameEnd = 0;
  const bool braced = !atEnd() && current() == '{';
  if (braced) {
    nameStart = offset_ + 1;
    nameEnd = wordRunEnd(nameStart);
    if (nameEnd >= text_.size() || text_[nameEnd] != '}') {
      fail(token.position, "missing '}' after '${'");
    }
  } else {
    nameEnd = wordRunEnd(nameStart);
  }
  if (nameEnd == nameStart) fail(token.position, "expected a macro name after '$'");
  token.text = std::string(text_.substr(nameStart, nameEnd - nameStart));
  const std::size_t end = braced ? nameEnd + 1 : nameEnd;
  while (offset_ < end) advance();
}

}  // namespace sphcast::dictionary
