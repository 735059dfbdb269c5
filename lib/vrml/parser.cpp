#include "vrml/parser.h"

#include "vrml/lexer.h"
#include "vrml/proto.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <climits>
#include <limits>
#include <string>
#include <unordered_map>

namespace cadlod::vrml {
namespace {

bool isIndexField(std::string_view name)
{
    return name == "index" || (name.size() > 5 && name.substr(name.size() - 5) == "Index");
}

// Exporters print non-finite values as words (nan, -inf, Infinity); read inside a number
// list they must keep their place, or every later value would shift silently.
bool nonFiniteNumberWord(std::string_view w, float& value)
{
    std::string lower;
    for (char c : w) lower.push_back(char(std::tolower(static_cast<unsigned char>(c))));
    const bool negative = !lower.empty() && lower[0] == '-';
    if (!lower.empty() && (lower[0] == '-' || lower[0] == '+')) lower.erase(0, 1);
    if (lower == "nan") value = std::numeric_limits<float>::quiet_NaN();
    else if (lower == "inf" || lower == "infinity") value = std::numeric_limits<float>::infinity();
    else return false;
    if (negative) value = -value;
    return true;
}

// The fields that place geometry: Transform's translation and center, VRML 1.0's
// Translation, Transform and MatrixTransform.
bool keepsExactNumbers(std::string_view name)
{
    return name == "translation" || name == "center" || name == "matrix";
}

// A decimal number in double precision; `single` (the float it reads as) for forms only
// the float reader knows (hexadecimal, out of range).
double toDouble(std::string_view text, float single)
{
    if (!text.empty() && text.front() == '+')
        text.remove_prefix(1);
    double value = 0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
    if (r.ec != std::errc() || r.ptr != text.data() + text.size() || !std::isfinite(value))
        return single;
    return value;
}

bool isInterfaceKeyword(std::string_view w)
{
    return w == "field" || w == "exposedField" || w == "eventIn" || w == "eventOut" ||
           w == "inputOnly" || w == "outputOnly" || w == "initializeOnly" || w == "inputOutput";
}

bool declHasValue(std::string_view w)
{
    return w == "field" || w == "exposedField" || w == "initializeOnly" || w == "inputOutput";
}

class Parser {
public:
    Parser(std::string_view text, const std::string& fileName, Diagnostics& diag, const ParseOptions& options)
        : lex_(text, fileName), diag_(diag), options_(options)
    {
        defScopes_.emplace_back();
        protoScopes_.emplace_back();
        const double relative = options.maxProtoCopiesPerInputByte * double(text.size());
        protoCopyLimit_ = relative > double(options.maxProtoCopies) ? size_t(relative) : options.maxProtoCopies;
    }

    ParsedFile run()
    {
        ParsedFile file;
        parseStatements(file.roots, file.rootUseSites, TokenKind::End);
        file.protos = protoScopes_.front();
        file.error = fatal_;
        return file;
    }

private:
    bool failed() const { return failed_; }

    void fail(const Token& at, const std::string& message)
    {
        if (failed_) return;
        failed_ = true;
        diag_.warn("syntax error", lex_.location(at), message + "; the rest of the file is ignored");
    }

    bool expect(TokenKind kind, const char* what)
    {
        const Token t = lex_.next();
        if (t.kind == kind) return true;
        fail(t, std::string("expected ") + what + ", found " + describe(t));
        return false;
    }

    static std::string describe(const Token& t)
    {
        switch (t.kind) {
        case TokenKind::End: return "end of file (truncated?)";
        case TokenKind::Bad: return "'" + std::string(t.text) + "'";
        case TokenKind::String: return "a string";
        default: return "'" + std::string(t.text) + "'";
        }
    }

    std::string word(const char* what)
    {
        const Token t = lex_.next();
        if (t.kind == TokenKind::Word) return std::string(t.text);
        fail(t, std::string("expected ") + what + ", found " + describe(t));
        return {};
    }

    void reportProgress()
    {
        if (!options_.progress) return;
        const size_t done = lex_.offset();
        if (done >= nextProgress_) {
            options_.progress(done, lex_.size());
            nextProgress_ = done + (size_t(1) << 20);
        }
    }

    void parseStatements(std::vector<NodePtr>& out, std::vector<UseSite>& useSites, TokenKind terminator)
    {
        while (!failed()) {
            const Token& t = lex_.peek();
            if (t.kind == terminator || t.kind == TokenKind::End) return;
            if (t.kind != TokenKind::Word) {
                fail(t, "expected a node, found " + describe(t));
                return;
            }
            if (!parseStatementKeyword()) appendNodeAfter(lex_.next(), out, useSites);
        }
    }

    // PROTO, EXTERNPROTO, ROUTE and X3D header statements; false when the next word is none.
    bool parseStatementKeyword()
    {
        if (!isStatementKeyword(lex_.peek().text)) return false;
        parseStatementKeywordAfter(lex_.next());
        return true;
    }

    static bool isStatementKeyword(std::string_view w)
    {
        return w == "PROTO" || w == "EXTERNPROTO" || w == "ROUTE" || w == "PROFILE" || w == "COMPONENT" ||
               w == "META" || w == "IMPORT" || w == "EXPORT";
    }

    bool parseStatementKeywordAfter(const Token& t)
    {
        const std::string_view w = t.text;
        if (w == "PROTO") {
            parseProto();
        } else if (w == "EXTERNPROTO") {
            parseExternProto();
        } else if (w == "ROUTE") {  // ROUTE a.b TO c.d: events are irrelevant to geometry
            for (int i = 0; i < 3 && !failed(); ++i) word("ROUTE part");
        } else if (w == "PROFILE" || w == "COMPONENT") {
            word("X3D profile or component");
        } else if (w == "META") {
            lex_.next();
            lex_.next();
        } else if (w == "IMPORT" || w == "EXPORT") {
            word("name");
            if (lex_.peek().kind == TokenKind::Word && lex_.peek().text == "AS") {
                lex_.next();
                word("name");
            }
        } else {
            return false;
        }
        return true;
    }

    NodePtr parseNode()
    {
        const Token t = lex_.next();
        if (t.kind != TokenKind::Word) {
            fail(t, "expected a node, found " + describe(t));
            return nullptr;
        }
        return parseNodeAfter(t);
    }

    // Parses the node starting at `t` and appends it (if any) to `nodes`, remembering a USE.
    void appendNodeAfter(const Token& t, std::vector<NodePtr>& nodes, std::vector<UseSite>& useSites)
    {
        NodePtr n = parseNodeAfter(t);
        if (!n) return;
        if (t.text == "USE") useSites.push_back({nodes.size(), lex_.location(t)});
        nodes.push_back(std::move(n));
    }

    NodePtr parseNodeAfter(const Token& t)
    {
        if (t.text == "NULL") return nullptr;
        if (t.text == "USE") {
            const Token nameTok = lex_.peek();
            const std::string name = word("a DEF name after USE");
            if (failed()) return nullptr;
            if (NodePtr n = lookupDef(name)) {
                ++n->useCount;
                return n;
            }
            diag_.warn("undefined USE", lex_.location(nameTok), "USE " + name + " has no DEF before it");
            return nullptr;
        }
        if (t.text == "DEF") {
            const std::string name = word("a name after DEF");
            if (failed()) return nullptr;
            NodePtr n = parseNode();
            if (n) {
                n->defName = name;
                defScopes_.back()[name] = n;  // the most recent DEF wins
            }
            return n;
        }
        return parseNodeBody(t);
    }

    NodePtr parseNodeBody(const Token& typeTok)
    {
        if (++depth_ > options_.maxDepth) {
            fail(typeTok, "nesting deeper than " + std::to_string(options_.maxDepth) + " levels");
            --depth_;
            return nullptr;
        }
        reportProgress();
        auto node = std::make_shared<Node>();
        node->type = std::string(typeTok.text);
        node->where = lex_.location(typeTok);
        if (expect(TokenKind::LBrace, ("'{' after " + node->type).c_str())) parseFields(*node);
        --depth_;
        if (std::shared_ptr<ProtoDecl> proto = lookupProto(node->type)) return instantiate(*proto, *node);
        return node;
    }

    void parseFields(Node& node)
    {
        while (!failed()) {
            const Token t = lex_.next();
            if (t.kind == TokenKind::RBrace) return;
            if (t.kind != TokenKind::Word) {
                fail(t, "expected a field name or '}' in " + node.type + ", found " + describe(t));
                return;
            }
            if (t.text == "DEF" || t.text == "USE") {
                appendNodeAfter(t, node.children, node.childUseSites);
                continue;
            }
            if ((t.text == "ROUTE" || t.text == "PROTO" || t.text == "EXTERNPROTO") && parseStatementKeywordAfter(t))
                continue;
            if (isInterfaceKeyword(t.text)) {
                parseInterfaceDecl(t.text, node.fields);
                continue;
            }
            if (lex_.peek().kind == TokenKind::LBrace) {  // VRML 1.0 child node
                if (NodePtr child = parseNodeBody(t)) node.children.push_back(std::move(child));
                continue;
            }
            Field f;
            f.name = std::string(t.text);
            f.value = parseValue(f.name);
            node.fields.push_back(std::move(f));
        }
    }

    void parseInterfaceDecl(std::string_view keyword, std::vector<Field>& out)
    {
        word("a field type");
        Field f;
        f.name = word("a field name");
        if (failed()) return;
        const Token& next = lex_.peek();
        if (next.kind == TokenKind::Word && next.text == "IS") {
            f.value = parseValue(f.name);
        } else if (declHasValue(keyword) && next.kind != TokenKind::RBrace && next.kind != TokenKind::RBracket &&
                   !(next.kind == TokenKind::Word && isInterfaceKeyword(next.text))) {
            f.value = parseValue(f.name);
        }
        out.push_back(std::move(f));
    }

    FieldValue parseValue(const std::string& name)
    {
        FieldValue v;
        const Token& t = lex_.peek();
        switch (t.kind) {
        case TokenKind::Number:
            readNumbers(name, v);
            break;
        case TokenKind::String:
            v.kind = FieldValue::Kind::Strings;
            v.strings.push_back(Lexer::unescape(lex_.next().text));
            break;
        case TokenKind::LBracket:
            lex_.next();
            parseList(name, v);
            break;
        case TokenKind::LParen:
            lex_.next();
            parseBitMask(v);
            break;
        case TokenKind::Word:
            parseWordValue(v);
            break;
        case TokenKind::RBrace:
            break;  // a declaration without value
        default:
            fail(t, "expected a value for field " + name + ", found " + describe(t));
        }
        return v;
    }

    void readNumbers(const std::string& name, FieldValue& v)
    {
        if (keepsExactNumbers(name)) {
            readExactNumbers(v);
            return;
        }
        if (isIndexField(name)) {
            if (!v.ints) v.ints = std::make_shared<std::vector<int32_t>>();
            v.kind = FieldValue::Kind::Ints;
            lex_.readInts(*v.ints);
        } else {
            if (!v.floats) v.floats = std::make_shared<std::vector<float>>();
            v.kind = FieldValue::Kind::Floats;
            lex_.readFloats(*v.floats);
        }
        if (lex_.peek().kind == TokenKind::Number) fail(lex_.peek(), "bad number");
    }

    // Each number as a float (as every other field reads it) and as a double.
    void readExactNumbers(FieldValue& v)
    {
        if (!v.floats) v.floats = std::make_shared<std::vector<float>>();
        if (!v.exact) v.exact = std::make_shared<std::vector<double>>(v.floats->begin(), v.floats->end());
        v.kind = FieldValue::Kind::Floats;
        while (lex_.peek().kind == TokenKind::Number) {
            float single = 0;
            if (!Lexer::toFloat(lex_.peek().text, single)) {
                fail(lex_.peek(), "bad number");
                return;
            }
            v.floats->push_back(single);
            v.exact->push_back(toDouble(lex_.next().text, single));
        }
    }

    bool readNonFiniteNumber(const std::string& name, const Token& w, FieldValue& v)
    {
        float value = 0;
        if (!nonFiniteNumberWord(w.text, value)) return false;
        diag_.warn("bad number", lex_.location(w),
                   "'" + std::string(w.text) + "' in the value of " + name + " is not a finite number");
        if (isIndexField(name)) {
            if (!v.ints) v.ints = std::make_shared<std::vector<int32_t>>();
            v.kind = FieldValue::Kind::Ints;
            v.ints->push_back(INT32_MIN);  // an invalid index
        } else {
            if (!v.floats) v.floats = std::make_shared<std::vector<float>>();
            v.kind = FieldValue::Kind::Floats;
            v.floats->push_back(value);
        }
        readNumbers(name, v);
        return true;
    }

    void parseList(const std::string& name, FieldValue& v)
    {
        while (!failed()) {
            const Token& t = lex_.peek();
            switch (t.kind) {
            case TokenKind::RBracket:
                lex_.next();
                return;
            case TokenKind::Number:
                readNumbers(name, v);
                break;
            case TokenKind::String:
                v.kind = FieldValue::Kind::Strings;
                v.strings.push_back(Lexer::unescape(lex_.next().text));
                break;
            case TokenKind::Word: {
                const Token w = lex_.next();
                if (readNonFiniteNumber(name, w, v)) break;
                if (w.text == "DEF" || w.text == "USE" || w.text == "NULL" || lex_.peek().kind == TokenKind::LBrace) {
                    v.kind = FieldValue::Kind::Nodes;
                    appendNodeAfter(w, v.nodes, v.useSites);
                } else if (w.text != "ROUTE" || !parseStatementKeywordAfter(w)) {
                    v.kind = FieldValue::Kind::Words;
                    v.strings.emplace_back(w.text);
                }
                break;
            }
            default:
                fail(t, "unexpected " + describe(t) + " in the value of " + name);
                return;
            }
        }
    }

    void parseBitMask(FieldValue& v)
    {
        v.kind = FieldValue::Kind::Words;
        while (!failed()) {
            const Token t = lex_.next();
            if (t.kind == TokenKind::RParen) return;
            if (t.kind == TokenKind::Word) v.strings.emplace_back(t.text);
            else if (t.kind != TokenKind::Bar) fail(t, "unexpected " + describe(t) + " in a bit mask");
        }
    }

    void parseWordValue(FieldValue& v)
    {
        const Token w = lex_.next();
        if (w.text == "IS") {
            v.kind = FieldValue::Kind::IsRef;
            v.strings.push_back(word("a proto field name after IS"));
            return;
        }
        if (w.text == "DEF" || w.text == "USE" || w.text == "NULL" || lex_.peek().kind == TokenKind::LBrace) {
            v.kind = FieldValue::Kind::Nodes;
            appendNodeAfter(w, v.nodes, v.useSites);
            return;
        }
        v.kind = FieldValue::Kind::Words;
        v.strings.emplace_back(w.text);
        while (lex_.peek().kind == TokenKind::Bar) {  // VRML 1.0 mask without parentheses
            lex_.next();
            v.strings.push_back(word("a bit mask value"));
        }
    }

    void parseProtoInterface(ProtoDecl& decl)
    {
        if (!expect(TokenKind::LBracket, "'[' after the PROTO name")) return;
        while (!failed()) {
            const Token t = lex_.next();
            if (t.kind == TokenKind::RBracket) return;
            if (t.kind != TokenKind::Word || !isInterfaceKeyword(t.text)) {
                fail(t, "expected a field declaration in " + decl.name + ", found " + describe(t));
                return;
            }
            parseInterfaceDecl(t.text, decl.interface);
        }
    }

    void parseProto()
    {
        auto decl = std::make_shared<ProtoDecl>();
        decl->name = word("a PROTO name");
        parseProtoInterface(*decl);
        const Token brace = lex_.peek();
        if (!expect(TokenKind::LBrace, "'{' opening the PROTO body")) return;
        // PROTOs nest inside PROTO bodies: they count towards the nesting limit like nodes.
        if (++depth_ > options_.maxDepth) {
            fail(brace, "nesting deeper than " + std::to_string(options_.maxDepth) + " levels");
            --depth_;
            return;
        }
        defScopes_.emplace_back();
        protoScopes_.emplace_back();
        std::vector<UseSite> bodyUseSites;  // only the body's first node is instantiated
        parseStatements(decl->body, bodyUseSites, TokenKind::RBrace);
        defScopes_.pop_back();
        protoScopes_.pop_back();
        --depth_;
        if (expect(TokenKind::RBrace, "'}' closing the PROTO body")) protoScopes_.back()[decl->name] = decl;
    }

    void parseExternProto()
    {
        auto decl = std::make_shared<ProtoDecl>();
        decl->external = true;
        decl->name = word("an EXTERNPROTO name");
        parseProtoInterface(*decl);
        FieldValue urls = parseValue("url");
        decl->urls = urls.strings;
        if (!failed()) protoScopes_.back()[decl->name] = decl;
    }

    NodePtr instantiate(ProtoDecl& proto, const Node& instance)
    {
        ProtoDecl* body = &proto;
        if (proto.external) {
            if (!proto.resolveAttempted) {
                proto.resolveAttempted = true;
                for (const std::string& url : proto.urls) {
                    if (options_.externProto) proto.resolved = options_.externProto(url, proto.name);
                    if (proto.resolved) break;
                }
                if (!proto.resolved)
                    diag_.warn("missing EXTERNPROTO", instance.where,
                               "cannot load EXTERNPROTO " + proto.name + "; its instances are skipped");
            }
            if (!proto.resolved) return nullptr;
            body = proto.resolved.get();
        }
        if (!admitCopies(*body, instance)) return nullptr;
        NodePtr n = instantiateProto(*body, instance);
        if (n) n->where = instance.where;
        return n;
    }

    bool admitCopies(ProtoDecl& body, const Node& instance)
    {
        const size_t copies = instanceNodeCount(body);
        if (protoCopies_ + copies <= protoCopyLimit_) {
            protoCopies_ += copies;
            return true;
        }
        fatal_ = instance.where + ": PROTO " + instance.type + " instance would make the PROTO copies exceed " +
                 std::to_string(protoCopyLimit_) + " nodes (instancing limit)";
        failed_ = true;
        return false;
    }

    NodePtr lookupDef(const std::string& name) const
    {
        const auto& scope = defScopes_.back();
        auto it = scope.find(name);
        return it == scope.end() ? nullptr : it->second;
    }

    std::shared_ptr<ProtoDecl> lookupProto(const std::string& name) const
    {
        for (auto s = protoScopes_.rbegin(); s != protoScopes_.rend(); ++s) {
            auto it = s->find(name);
            if (it != s->end()) return it->second;
        }
        return nullptr;
    }

    Lexer lex_;
    Diagnostics& diag_;
    const ParseOptions& options_;
    std::vector<std::unordered_map<std::string, NodePtr>> defScopes_;
    std::vector<ProtoTable> protoScopes_;
    bool failed_ = false;
    std::string fatal_;  // ends the import (ParsedFile::error)
    size_t protoCopies_ = 0;  // nodes copied by PROTO instances so far
    size_t protoCopyLimit_ = 0;
    int depth_ = 0;
    size_t nextProgress_ = 0;
};

}  // namespace

VrmlVersion detectVersion(std::string_view text)
{
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    if (text.substr(0, 10) == "#VRML V2.0") return VrmlVersion::V2;
    if (text.substr(0, 10) == "#VRML V1.0") return VrmlVersion::V1;
    if (text.substr(0, 4) == "#X3D") return VrmlVersion::V2;
    return VrmlVersion::Unknown;
}

ParsedFile parseVrml(std::string_view text, const std::string& fileName, Diagnostics& diag,
                     const ParseOptions& options)
{
    const VrmlVersion version = detectVersion(text);
    if (version == VrmlVersion::Unknown) {
        ParsedFile file;
        file.error = fileName + ":1:1: not a VRML file (expected a '#VRML V2.0 utf8' or '#VRML V1.0 ascii' header)";
        return file;
    }
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 byte order mark
    ParsedFile file = Parser(text, fileName, diag, options).run();
    file.version = version;
    return file;
}

}  // namespace cadlod::vrml
