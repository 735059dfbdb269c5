// Lexical grammar: comments, commas, strings, hex, locale independence, positions.
#include "vrml/lexer.h"

#include <gtest/gtest.h>

#include <clocale>

using namespace cadlod::vrml;

TEST(VrmlLexer, SkipsCommentsAndCommasAndTracksLineAndColumn)
{
    Lexer lex("# header\nShape { # comment\n  field 1,2 , 3\n}", "f.wrl");
    Token t = lex.next();
    EXPECT_EQ(t.kind, TokenKind::Word);
    EXPECT_EQ(t.text, "Shape");
    EXPECT_EQ(t.line, 2);
    EXPECT_EQ(t.column, 1);
    EXPECT_EQ(lex.next().kind, TokenKind::LBrace);
    t = lex.next();
    EXPECT_EQ(t.text, "field");
    EXPECT_EQ(lex.location(t), "f.wrl:3:3");
    std::vector<float> v;
    lex.readFloats(v);
    EXPECT_EQ(v, (std::vector<float>{1, 2, 3}));
    EXPECT_EQ(lex.next().kind, TokenKind::RBrace);
    EXPECT_EQ(lex.next().kind, TokenKind::End);
}

TEST(VrmlLexer, StringsKeepEscapedQuotesAndBackslashes)
{
    Lexer lex(R"("a \"quoted\" \\ word" "multi
line")", "f.wrl");
    Token t = lex.next();
    ASSERT_EQ(t.kind, TokenKind::String);
    EXPECT_EQ(Lexer::unescape(t.text), "a \"quoted\" \\ word");
    t = lex.next();
    EXPECT_EQ(Lexer::unescape(t.text), "multi\nline");
    EXPECT_EQ(lex.peek().line, 2);
}

TEST(VrmlLexer, UnterminatedStringIsABadToken)
{
    Lexer lex("\"never closed", "f.wrl");
    EXPECT_EQ(lex.next().kind, TokenKind::Bad);
}

TEST(VrmlLexer, NumbersInEveryNotation)
{
    Lexer lex("-1.5e2 +3 .25 -.5 0x1F 0XFF 7. 1E-3", "f.wrl");
    std::vector<float> v;
    lex.readFloats(v);
    ASSERT_EQ(v.size(), 8u);
    EXPECT_FLOAT_EQ(v[0], -150.0f);
    EXPECT_FLOAT_EQ(v[1], 3.0f);
    EXPECT_FLOAT_EQ(v[2], 0.25f);
    EXPECT_FLOAT_EQ(v[3], -0.5f);
    EXPECT_FLOAT_EQ(v[4], 31.0f);
    EXPECT_FLOAT_EQ(v[5], 255.0f);
    EXPECT_FLOAT_EQ(v[6], 7.0f);
    EXPECT_FLOAT_EQ(v[7], 0.001f);
}

TEST(VrmlLexer, IntegersStopAtSeparatorsAndWords)
{
    Lexer lex("0 1 2 -1, 3,4,5,-1] rest", "f.wrl");
    std::vector<int32_t> v;
    lex.readInts(v);
    EXPECT_EQ(v, (std::vector<int32_t>{0, 1, 2, -1, 3, 4, 5, -1}));
    EXPECT_EQ(lex.next().kind, TokenKind::RBracket);
    EXPECT_EQ(lex.next().text, "rest");
}

TEST(VrmlLexer, NumberParsingIgnoresTheLocale)
{
    const char* set = std::setlocale(LC_NUMERIC, "de_DE.UTF-8");
    if (!set) set = std::setlocale(LC_NUMERIC, "fr_FR.UTF-8");
    Lexer lex("1.5 2,5", "f.wrl");  // comma separates values, never a decimal point
    std::vector<float> v;
    lex.readFloats(v);
    std::setlocale(LC_NUMERIC, "C");
    EXPECT_EQ(v, (std::vector<float>{1.5f, 2.0f, 5.0f}));
}
