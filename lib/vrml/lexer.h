// VRML tokenizer over an in-memory text (VRML97 and VRML 1.0 share the lexical
// grammar): '#' comments, commas as whitespace, strings with \" and \\ escapes,
// decimal/hex numbers parsed locale-independently with std::from_chars.
// Tokens are views into the text; MF number arrays are read straight into vectors.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace cadlod::vrml {

enum class TokenKind { End, Word, Number, String, LBrace, RBrace, LBracket, RBracket, LParen, RParen, Bar, Bad };

struct Token {
    TokenKind kind = TokenKind::End;
    std::string_view text;  // for String: the raw contents between the quotes
    int line = 1;
    int column = 1;
};

class Lexer {
public:
    Lexer(std::string_view text, std::string fileName);

    const Token& peek();
    Token next();
    bool atEnd() { return peek().kind == TokenKind::End; }

    // Fast paths for MF arrays: when the next token is a number, consume it.
    bool readFloat(float& value);
    bool readInt(int32_t& value);
    // Reads numbers until the next non-number token.
    void readFloats(std::vector<float>& out);
    void readInts(std::vector<int32_t>& out);

    std::string location(const Token& t) const;
    std::string location();  // of the next token
    const std::string& fileName() const { return fileName_; }
    size_t offset() const { return size_t(p_ - begin_); }
    size_t size() const { return size_t(end_ - begin_); }

    static std::string unescape(std::string_view raw);
    static bool toFloat(std::string_view text, float& value);

private:
    void skipSpace();
    Token lex();
    bool numberAhead();
    int column() const { return int(p_ - lineStart_) + 1; }

    const char* begin_;
    const char* p_;
    const char* end_;
    const char* lineStart_;
    int line_ = 1;
    std::string fileName_;
    Token peeked_;
    bool hasPeeked_ = false;
};

}  // namespace cadlod::vrml
