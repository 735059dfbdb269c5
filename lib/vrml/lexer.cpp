#include "vrml/lexer.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace cadlod::vrml {
namespace {

bool isNumberStart(char c, char next)
{
    if (c >= '0' && c <= '9') return true;
    if (c == '-' || c == '+') return (next >= '0' && next <= '9') || next == '.';
    return c == '.' && next >= '0' && next <= '9';
}

// VRML97 identifiers exclude control chars, space and " # ' , [ \ ] { }; we also stop
// at ( ) | for VRML 1.0 bit masks.
bool isWordChar(char c)
{
    const unsigned char u = static_cast<unsigned char>(c);
    if (u <= 0x20 || u == 0x7f) return false;
    switch (c) {
    case '"': case '#': case '\'': case ',': case '[': case '\\': case ']': case '{': case '}':
    case '(': case ')': case '|':
        return false;
    default:
        return true;
    }
}

// Clinger's fast path: up to 15 significant digits and a power of ten up to 22 convert
// exactly through double; anything else (or a malformed number) returns nullptr and the
// caller uses std::from_chars. Locale-independent by construction.
const char* parseSimpleFloat(const char* p, const char* end, float& value)
{
    static const double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    const bool negative = p < end && *p == '-';
    if (negative) ++p;
    uint64_t mantissa = 0;
    int digits = 0, exponent = 0;
    const char* start = p;
    while (p < end && unsigned(*p - '0') < 10) {
        mantissa = mantissa * 10 + unsigned(*p++ - '0');
        if (mantissa) ++digits;
    }
    if (p < end && *p == '.') {
        ++p;
        while (p < end && unsigned(*p - '0') < 10) {
            mantissa = mantissa * 10 + unsigned(*p++ - '0');
            if (mantissa) ++digits;
            --exponent;
        }
    }
    if (p == start || (p == start + 1 && *start == '.')) return nullptr;
    if (p < end && (*p == 'e' || *p == 'E')) {
        const char* q = p + 1;
        const bool negExp = q < end && *q == '-';
        if (q < end && (*q == '-' || *q == '+')) ++q;
        if (q >= end || unsigned(*q - '0') >= 10) return nullptr;
        int e = 0;
        while (q < end && unsigned(*q - '0') < 10 && e < 10000) e = e * 10 + (*q++ - '0');
        exponent += negExp ? -e : e;
        p = q;
    }
    if (digits > 15 || exponent < -22 || exponent > 22) return nullptr;
    double v = double(mantissa);
    v = exponent < 0 ? v / kPow10[-exponent] : v * kPow10[exponent];
    value = float(negative ? -v : v);
    return p;
}

const char* parseHex(const char* p, const char* end, int64_t& v)
{
    auto r = std::from_chars(p + 2, end, v, 16);
    return r.ec == std::errc() ? r.ptr : nullptr;
}

}  // namespace

Lexer::Lexer(std::string_view text, std::string fileName)
    : begin_(text.data()), p_(text.data()), end_(text.data() + text.size()), lineStart_(text.data()),
      fileName_(std::move(fileName))
{
}

void Lexer::skipSpace()
{
    while (p_ < end_) {
        const char c = *p_;
        if (c == '\n') {
            ++line_;
            lineStart_ = ++p_;
        } else if (c == ' ' || c == '\t' || c == '\r' || c == ',') {
            ++p_;
        } else if (c == '#') {
            while (p_ < end_ && *p_ != '\n') ++p_;
        } else {
            return;
        }
    }
}

bool Lexer::numberAhead()
{
    if (hasPeeked_) return peeked_.kind == TokenKind::Number;
    skipSpace();
    return p_ < end_ && isNumberStart(*p_, p_ + 1 < end_ ? p_[1] : '\0');
}

Token Lexer::lex()
{
    skipSpace();
    Token t;
    t.line = line_;
    t.column = column();
    if (p_ >= end_) return t;
    const char c = *p_;
    const char next = p_ + 1 < end_ ? p_[1] : '\0';
    const char* start = p_;
    auto single = [&](TokenKind k) {
        t.kind = k;
        t.text = std::string_view(p_, 1);
        ++p_;
        return t;
    };
    switch (c) {
    case '{': return single(TokenKind::LBrace);
    case '}': return single(TokenKind::RBrace);
    case '[': return single(TokenKind::LBracket);
    case ']': return single(TokenKind::RBracket);
    case '(': return single(TokenKind::LParen);
    case ')': return single(TokenKind::RParen);
    case '|': return single(TokenKind::Bar);
    case '"': {
        ++p_;
        const char* s = p_;
        while (p_ < end_ && *p_ != '"') {
            if (*p_ == '\\' && p_ + 1 < end_) ++p_;
            if (*p_ == '\n') {
                ++line_;
                lineStart_ = p_ + 1;
            }
            ++p_;
        }
        if (p_ >= end_) {
            t.kind = TokenKind::Bad;
            t.text = "unterminated string";
            return t;
        }
        t.kind = TokenKind::String;
        t.text = std::string_view(s, size_t(p_ - s));
        ++p_;
        return t;
    }
    default: break;
    }
    if (isNumberStart(c, next)) {
        t.kind = TokenKind::Number;
        while (p_ < end_ && isWordChar(*p_)) ++p_;
        t.text = std::string_view(start, size_t(p_ - start));
        return t;
    }
    if (isWordChar(c)) {
        t.kind = TokenKind::Word;
        while (p_ < end_ && isWordChar(*p_)) ++p_;
        t.text = std::string_view(start, size_t(p_ - start));
        return t;
    }
    t.kind = TokenKind::Bad;
    t.text = std::string_view(p_, 1);
    ++p_;
    return t;
}

const Token& Lexer::peek()
{
    if (!hasPeeked_) {
        peeked_ = lex();
        hasPeeked_ = true;
    }
    return peeked_;
}

Token Lexer::next()
{
    if (hasPeeked_) {
        hasPeeked_ = false;
        return peeked_;
    }
    return lex();
}

// std::from_chars leaves the value untouched when it is out of range: parse through double
// and round explicitly, so 1e-50 reads as 0 and 1e39 as infinity (a point the face emitter
// then refuses) instead of silently repeating the previous number.
static bool parseFloatBeyondRange(const char* p, const char* end, float& value)
{
    double d = 0;
    const auto r = std::from_chars(p, end, d);
    if (r.ec == std::errc::result_out_of_range) {
        const bool negative = p < end && *p == '-';
        const char* e = std::find_if(p, r.ptr, [](char c) { return c == 'e' || c == 'E'; });
        const bool tiny = e + 1 < r.ptr && e[1] == '-';
        d = tiny ? 0.0 : std::numeric_limits<double>::infinity();
        if (negative) d = -d;
    } else if (r.ec != std::errc()) {
        return false;
    }
    if (std::fabs(d) > double(std::numeric_limits<float>::max())) value = d < 0 ? -HUGE_VALF : HUGE_VALF;
    else value = float(d);
    return true;
}

bool Lexer::toFloat(std::string_view text, float& value)
{
    const char* p = text.data();
    const char* end = p + text.size();
    if (p < end && *p == '+') ++p;
    const bool negative = p < end && *p == '-';
    const char* digits = negative ? p + 1 : p;
    if (end - digits > 2 && digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X')) {
        int64_t v = 0;
        if (!parseHex(digits, end, v)) return false;
        value = float(negative ? -v : v);
        return true;
    }
    return parseFloatBeyondRange(p, end, value);
}

bool Lexer::readFloat(float& value)
{
    if (hasPeeked_) {
        if (peeked_.kind != TokenKind::Number || !toFloat(peeked_.text, value)) return false;
        hasPeeked_ = false;
        return true;
    }
    skipSpace();
    if (p_ >= end_ || !isNumberStart(*p_, p_ + 1 < end_ ? p_[1] : '\0')) return false;
    const char* p = *p_ == '+' ? p_ + 1 : p_;
    if (const char* q = parseSimpleFloat(p, end_, value); q && (q >= end_ || !isWordChar(*q))) {
        p_ = q;
        return true;
    }
    auto r = std::from_chars(p, end_, value);
    if (r.ec != std::errc() || (r.ptr < end_ && isWordChar(*r.ptr) && *r.ptr != '-')) {
        // Hex, or something odd like 1.#QNAN: take the slow path on the whole token.
        const Token& t = peek();
        if (!toFloat(t.text, value)) return false;
        hasPeeked_ = false;
        return true;
    }
    p_ = r.ptr;
    return true;
}

bool Lexer::readInt(int32_t& value)
{
    if (!hasPeeked_) {
        skipSpace();
        // Hand-rolled decimal fast path (indices are short integers); anything unusual
        // (overflow, '.', exponent, hex) falls through to the float path.
        const char* p = p_;
        const bool negative = p < end_ && *p == '-';
        if (negative) ++p;
        const char* digits = p;
        int64_t v = 0;
        while (p < end_ && unsigned(*p - '0') < 10 && p - digits < 10) v = v * 10 + (*p++ - '0');
        if (p > digits && (p >= end_ || !isWordChar(*p)) && v <= INT32_MAX) {
            value = int32_t(negative ? -v : v);
            p_ = p;
            return true;
        }
    }
    float f = 0;
    if (!readFloat(f)) return false;
    // Out of the int32 range: an invalid (negative, not -1) index, reported where it is used.
    value = f >= -2147483648.0f && f < 2147483648.0f ? int32_t(f) : INT32_MIN;
    return true;
}

void Lexer::readFloats(std::vector<float>& out)
{
    float v = 0;
    while (readFloat(v)) out.push_back(v);
}

void Lexer::readInts(std::vector<int32_t>& out)
{
    int32_t v = 0;
    while (readInt(v)) out.push_back(v);
}

std::string Lexer::location(const Token& t) const
{
    return fileName_ + ":" + std::to_string(t.line) + ":" + std::to_string(t.column);
}

std::string Lexer::location() { return location(peek()); }

std::string Lexer::unescape(std::string_view raw)
{
    std::string s;
    s.reserve(raw.size());
    for (size_t i = 0; i < raw.size(); ++i) {
        if (raw[i] == '\\' && i + 1 < raw.size()) ++i;
        s.push_back(raw[i]);
    }
    return s;
}

}  // namespace cadlod::vrml
