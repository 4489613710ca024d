#include "app/shader/glsl_syntax.h"

#include <cctype>
#include <stdexcept>

namespace shadelab::glsl {

namespace {

struct Token {
  enum class Kind { Name, Number, Punct, End } kind = Kind::End;
  std::string text;
  size_t begin = 0, end = 0;
  int line = 0;
};

bool nameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool nameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Tokens of source[from, to): comments and preprocessor lines skipped.
std::vector<Token> tokenize(std::string_view s, size_t from, size_t to, int line) {
  static const char* const kPuncts[] = {"<<=", ">>=", "++", "--", "+=", "-=", "*=", "/=", "%=", "&=", "|=",
                                        "^=",  "==",  "!=", "<=", ">=", "&&", "||", "^^", "<<", ">>"};
  std::vector<Token> out;
  bool lineStart = true;
  for (size_t i = from; i < to;) {
    const char c = s[i];
    if (c == '\n') {
      ++line;
      ++i;
      lineStart = true;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
      continue;
    }
    if (c == '/' && i + 1 < to && s[i + 1] == '/') {
      while (i < to && s[i] != '\n') ++i;
      continue;
    }
    if (c == '/' && i + 1 < to && s[i + 1] == '*') {
      i += 2;
      while (i + 1 < to && !(s[i] == '*' && s[i + 1] == '/')) line += s[i++] == '\n';
      i += 2;
      continue;
    }
    if (c == '#' && lineStart) {  // a preprocessor line, continuations included
      while (i < to && s[i] != '\n') {
        if (s[i] == '\\' && i + 1 < to && s[i + 1] == '\n') {
          ++line;
          ++i;
        }
        ++i;
      }
      continue;
    }
    lineStart = false;
    Token t;
    t.begin = i;
    t.line = line;
    if (nameStart(c)) {
      while (i < to && nameChar(s[i])) ++i;
      t.kind = Token::Kind::Name;
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               (c == '.' && i + 1 < to && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      while (i < to && (nameChar(s[i]) || s[i] == '.' ||
                        ((s[i] == '+' || s[i] == '-') && (s[i - 1] == 'e' || s[i - 1] == 'E') &&
                         !(s[t.begin] == '0' && t.begin + 1 < to && (s[t.begin + 1] == 'x' || s[t.begin + 1] == 'X')))))
        ++i;
      t.kind = Token::Kind::Number;
    } else {
      t.kind = Token::Kind::Punct;
      size_t n = 1;
      for (const char* p : kPuncts) {
        const size_t len = std::char_traits<char>::length(p);
        if (s.substr(i, len) == p) {
          n = len;
          break;
        }
      }
      i += n;
    }
    t.end = i;
    t.text = std::string(s.substr(t.begin, t.end - t.begin));
    out.push_back(std::move(t));
  }
  Token end;
  end.begin = end.end = to;
  end.line = line;
  out.push_back(end);
  return out;
}

struct ParseError : std::runtime_error {
  int line;
  ParseError(const std::string& what, int at) : std::runtime_error(what), line(at) {}
};

bool isQualifier(const std::string& w) {
  return w == "const" || w == "highp" || w == "mediump" || w == "lowp" || w == "precise" || w == "in" || w == "out" ||
         w == "inout" || w == "flat" || w == "smooth";
}

class Parser {
 public:
  Parser(std::vector<Token> tokens, Function& f) : t_(std::move(tokens)), f_(f) {}

  int block() {  // at '{'
    Stmt s;
    s.kind = Stmt::Kind::Block;
    s.begin = peek().begin;
    s.line = peek().line;
    expect("{");
    while (!at("}")) {
      if (peek().kind == Token::Kind::End) fail("the body ends before its closing '}'");
      s.body.push_back(statement());
    }
    s.end = next().end;
    return add(std::move(s));
  }

 private:
  const Token& peek(size_t k = 0) const { return t_[std::min(i_ + k, t_.size() - 1)]; }
  bool at(const char* text, size_t k = 0) const { return peek(k).kind != Token::Kind::End && peek(k).text == text; }
  const Token& next() {
    const Token& t = peek();
    if (i_ < t_.size() - 1) ++i_;
    return t;
  }
  [[noreturn]] void fail(const std::string& what) const { throw ParseError(what, peek().line); }
  const Token& expect(const char* text) {
    if (!at(text)) fail(std::string("expected '") + text + "' before '" + peek().text + "'");
    return next();
  }
  int add(Stmt s) {
    f_.stmts.push_back(std::move(s));
    return int(f_.stmts.size() - 1);
  }
  int add(Expr e) {
    f_.exprs.push_back(std::move(e));
    return int(f_.exprs.size() - 1);
  }
  size_t endOfPrevious() const { return t_[i_ - 1].end; }

  // Whether a declaration starts here: qualifiers, or a type followed by a name (brackets between).
  bool declarationAhead() const {
    size_t k = 0;
    if (peek().kind != Token::Kind::Name) return false;
    if (isQualifier(peek().text)) return true;
    ++k;
    if (at("[", k)) {  // float[3] a
      int depth = 0;
      for (; peek(k).kind != Token::Kind::End; ++k) {
        depth += at("[", k) - at("]", k);
        if (depth == 0) break;
      }
      ++k;
    }
    return peek(k).kind == Token::Kind::Name;
  }

  int statement() {
    Stmt s;
    s.begin = peek().begin;
    s.line = peek().line;
    const std::string w = peek().text;
    if (at("{")) return block();
    if (at(";")) {
      next();
      s.kind = Stmt::Kind::Empty;
    } else if (w == "if" && peek().kind == Token::Kind::Name) {
      next();
      s.kind = Stmt::Kind::If;
      expect("(");
      s.expr = expression();
      expect(")");
      s.body.push_back(statement());
      if (at("else")) {
        next();
        s.body.push_back(statement());
      }
      s.end = f_.stmts[s.body.back()].end;
      return add(std::move(s));
    } else if (w == "for") {
      next();
      s.kind = Stmt::Kind::For;
      s.headerBegin = expect("(").begin;
      if (declarationAhead())
        declaration(s);
      else if (!at(";"))
        expression();
      expect(";");
      if (!at(";")) expression();
      expect(";");
      if (!at(")")) expression();
      s.headerEnd = expect(")").end;
      s.declared.clear();  // the loop's counter is bookkeeping, not a value to trace
      s.body.push_back(statement());
      s.end = f_.stmts[s.body.back()].end;
      return add(std::move(s));
    } else if (w == "while") {
      next();
      s.kind = Stmt::Kind::While;
      expect("(");
      s.expr = expression();
      expect(")");
      s.body.push_back(statement());
      s.end = f_.stmts[s.body.back()].end;
      return add(std::move(s));
    } else if (w == "do") {
      next();
      s.kind = Stmt::Kind::Do;
      s.body.push_back(statement());
      if (!at("while")) fail("expected 'while' after a do loop's body");
      next();
      expect("(");
      s.expr = expression();
      expect(")");
      expect(";");
    } else if (w == "return") {
      next();
      s.kind = Stmt::Kind::Return;
      if (!at(";")) s.expr = expression();
      expect(";");
    } else if (w == "break" || w == "continue" || w == "discard") {
      next();
      s.kind = Stmt::Kind::Jump;
      expect(";");
    } else if (w == "switch") {
      fail("a switch statement (not traced)");
    } else if (declarationAhead()) {
      s.kind = Stmt::Kind::Declaration;
      declaration(s);
      expect(";");
    } else {
      s.kind = Stmt::Kind::Expression;
      s.expr = expression();
      expect(";");
    }
    s.end = endOfPrevious();
    return add(std::move(s));
  }

  std::string brackets() {  // "[3]" or "[]" as written, or ""
    std::string out;
    while (at("[")) {
      out += next().text;
      int depth = 1;
      while (depth > 0) {
        if (peek().kind == Token::Kind::End) fail("an unclosed '['");
        depth += at("[") - at("]");
        out += next().text;
      }
    }
    return out;
  }

  void declaration(Stmt& s) {
    bool constant = false;
    while (peek().kind == Token::Kind::Name && isQualifier(peek().text)) constant |= next().text == "const";
    if (peek().kind != Token::Kind::Name) fail("expected a type");
    std::string type = next().text;
    if (at("(")) fail("a struct declared inside a function (not traced)");
    type += brackets();
    for (;;) {
      Declarator d;
      d.constant = constant;
      if (peek().kind != Token::Kind::Name) fail("expected a name after the type '" + type + "'");
      d.name = next().text;
      d.type = type + brackets();
      if (at("=")) {
        next();
        d.init = assignment();
      }
      s.declared.push_back(std::move(d));
      if (!at(",")) break;
      next();
    }
  }

  Expr start(Expr::Kind kind) const {
    Expr e;
    e.kind = kind;
    e.begin = peek().begin;
    e.line = peek().line;
    return e;
  }
  int finish(Expr e) {
    e.end = endOfPrevious();
    return add(std::move(e));
  }
  // An operation lies on its operator's line (`a -\n b / c`: the division is on the second).
  int binary(Expr::Kind kind, const std::string& op, int lhs, int rhs, int line) {
    Expr e;
    e.kind = kind;
    e.text = op;
    e.args = {lhs, rhs};
    e.begin = f_.exprs[lhs].begin;
    e.line = line;
    e.end = f_.exprs[rhs].end;
    return add(std::move(e));
  }

  int expression() {
    int e = assignment();
    while (at(",")) {
      const int line = next().line;
      e = binary(Expr::Kind::Sequence, ",", e, assignment(), line);
    }
    return e;
  }

  int assignment() {
    const int lhs = ternary();
    static const char* const kOps[] = {"=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "|=", "^="};
    for (const char* op : kOps)
      if (at(op) && peek().kind == Token::Kind::Punct) {
        const int line = next().line;
        return binary(Expr::Kind::Assign, op, lhs, assignment(), line);
      }
    return lhs;
  }

  int ternary() {
    const int c = binaryLevel(0);
    if (!at("?")) return c;
    next();
    const int a = assignment();
    expect(":");
    const int b = assignment();
    Expr e;
    e.kind = Expr::Kind::Ternary;
    e.args = {c, a, b};
    e.begin = f_.exprs[c].begin;
    e.line = f_.exprs[c].line;
    e.end = f_.exprs[b].end;
    return add(std::move(e));
  }

  // Binary operators from the loosest (||) to the tightest (* / %).
  int binaryLevel(size_t level) {
    static const std::vector<std::vector<std::string>> kLevels = {
        {"||"},       {"^^"},     {"&&"},         {"|"}, {"^"}, {"&"}, {"==", "!="}, {"<", ">", "<=", ">="},
        {"<<", ">>"}, {"+", "-"}, {"*", "/", "%"}};
    if (level == kLevels.size()) return unary();
    int lhs = binaryLevel(level + 1);
    for (;;) {
      const Token& t = peek();
      if (t.kind != Token::Kind::Punct) return lhs;
      bool found = false;
      for (auto& op : kLevels[level]) found |= t.text == op;
      if (!found) return lhs;
      const Token& token = next();
      const std::string op = token.text;
      const int line = token.line;
      lhs = binary(Expr::Kind::Binary, op, lhs, binaryLevel(level + 1), line);
    }
  }

  int unary() {
    if (peek().kind == Token::Kind::Punct && (at("-") || at("+") || at("!") || at("~") || at("++") || at("--"))) {
      Expr e = start(Expr::Kind::Unary);
      e.text = next().text;
      e.args = {unary()};
      return finish(std::move(e));
    }
    return postfix(primary());
  }

  int postfix(int e) {
    for (;;) {
      if (at(".")) {
        next();
        Expr m;
        m.kind = Expr::Kind::Member;
        m.begin = f_.exprs[e].begin;
        m.line = f_.exprs[e].line;
        if (peek().kind != Token::Kind::Name) fail("expected a member name after '.'");
        m.text = next().text;
        m.args = {e};
        e = finish(std::move(m));
      } else if (at("[")) {
        next();
        Expr x;
        x.kind = Expr::Kind::Index;
        x.begin = f_.exprs[e].begin;
        x.line = f_.exprs[e].line;
        x.args = {e, expression()};
        expect("]");
        e = finish(std::move(x));
      } else if (at("++") || at("--")) {
        Expr p;
        p.kind = Expr::Kind::Postfix;
        p.begin = f_.exprs[e].begin;
        p.line = f_.exprs[e].line;
        p.text = next().text;
        p.args = {e};
        e = finish(std::move(p));
      } else {
        return e;
      }
    }
  }

  int primary() {
    const Token& t = peek();
    if (t.kind == Token::Kind::Number) {
      Expr e = start(Expr::Kind::Literal);
      e.text = next().text;
      return finish(std::move(e));
    }
    if (at("(")) {
      next();
      const int e = expression();
      expect(")");
      // The parentheses belong to the expression: a tap around it keeps the grouping.
      f_.exprs[e].begin = std::min(f_.exprs[e].begin, t.begin);
      f_.exprs[e].end = endOfPrevious();
      return e;
    }
    if (t.kind != Token::Kind::Name) fail("unexpected '" + t.text + "'");
    Expr e = start(Expr::Kind::Name);
    e.text = next().text;
    if (e.text == "true" || e.text == "false") {
      e.kind = Expr::Kind::Literal;
      return finish(std::move(e));
    }
    if (at("[") && declaredArrayType()) {  // float[3](...)
      e.text += brackets();
      e.arrayConstructor = true;
    }
    if (at("(")) {
      e.kind = Expr::Kind::Call;
      next();
      if (at("void")) next();
      while (!at(")")) {
        e.args.push_back(assignment());
        if (!at(",")) break;
        next();
      }
      expect(")");
    }
    return finish(std::move(e));
  }

  // At '[' after a name: whether brackets and then '(' follow (an array constructor).
  bool declaredArrayType() const {
    size_t k = 0;
    int depth = 0;
    for (; peek(k).kind != Token::Kind::End; ++k) {
      depth += at("[", k) - at("]", k);
      if (depth == 0) break;
    }
    return at("(", k + 1);
  }

  std::vector<Token> t_;
  size_t i_ = 0;
  Function& f_;
};

int lineAt(std::string_view s, size_t at) {
  int line = 1;
  for (size_t i = 0; i < at && i < s.size(); ++i) line += s[i] == '\n';
  return line;
}

// Every `name (` at the top level of `source` followed by a parameter list and a '{', as the
// offset of the name.
std::vector<size_t> definitionsOf(std::string_view s, const std::string& name) {
  std::vector<size_t> out;
  const std::vector<Token> t = tokenize(s, 0, s.size(), 1);
  int depth = 0;
  for (size_t i = 0; i + 1 < t.size(); ++i) {
    if (t[i].text == "{") ++depth;
    if (t[i].text == "}") --depth;
    if (depth != 0 || t[i].kind != Token::Kind::Name || t[i].text != name || t[i + 1].text != "(" || i == 0 ||
        t[i - 1].kind != Token::Kind::Name)
      continue;
    size_t k = i + 1;
    int parens = 0;
    for (; k < t.size(); ++k) {
      parens += (t[k].text == "(") - (t[k].text == ")");
      if (parens == 0) break;
    }
    if (k + 1 < t.size() && t[k + 1].text == "{") out.push_back(t[i].begin);
  }
  return out;
}

}  // namespace

bool isBasicType(const std::string& type) { return componentsOf(type) > 0; }

int componentsOf(const std::string& type) {
  if (type == "float" || type == "int" || type == "uint" || type == "bool") return 1;
  for (const char* prefix : {"vec", "ivec", "uvec", "bvec"}) {
    const std::string p = prefix;
    if (type.size() == p.size() + 1 && type.compare(0, p.size(), p) == 0 && type.back() >= '2' && type.back() <= '4')
      return type.back() - '0';
  }
  return 0;
}

std::string exprText(std::string_view source, const Expr& e) {
  std::string out;
  bool space = false;
  for (size_t i = e.begin; i < e.end && i < source.size(); ++i) {
    const char c = source[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      space = !out.empty();
      continue;
    }
    if (space) out += ' ';
    space = false;
    out += c;
  }
  return out;
}

bool parseFunction(std::string_view source, const std::string& name, Function& out, std::string& error) {
  const std::vector<size_t> starts = definitionsOf(source, name);
  if (starts.empty()) {
    error = "no definition of " + name + "()";
    return false;
  }
  for (size_t at : starts) {
    Function f;
    f.name = name;
    // The return type: the name before `name`, with its precision qualifier if any.
    size_t typeEnd = at;
    while (typeEnd > 0 && std::isspace(static_cast<unsigned char>(source[typeEnd - 1]))) --typeEnd;
    size_t typeBegin = typeEnd;
    while (typeBegin > 0 && nameChar(source[typeBegin - 1])) --typeBegin;
    f.returnType = std::string(source.substr(typeBegin, typeEnd - typeBegin));
    f.begin = typeBegin;
    const size_t open = source.find('(', at);
    int depth = 0;
    size_t close = open;
    for (; close < source.size(); ++close) {
      depth += (source[close] == '(') - (source[close] == ')');
      if (depth == 0) break;
    }
    // Parameters: "in vec3 N", "out float e", "highp vec2 uv", "sampler2D map", "void".
    std::vector<Token> p = tokenize(source, open + 1, close, lineAt(source, open));
    std::vector<std::string> words;
    const auto flush = [&] {
      if (words.empty() || (words.size() == 1 && words[0] == "void")) return;
      Param param;
      for (size_t k = 0; k + 2 < words.size(); ++k)
        if (words[k] == "in" || words[k] == "out" || words[k] == "inout") param.qualifier = words[k];
      param.name = words.back();
      param.type = words.size() >= 2 ? words[words.size() - 2] : "";
      f.params.push_back(param);
      words.clear();
    };
    for (auto& tk : p) {
      if (tk.kind == Token::Kind::End) break;
      if (tk.text == ",") {
        flush();
      } else if (tk.kind == Token::Kind::Name && tk.text != "const" && tk.text != "highp" && tk.text != "mediump" &&
                 tk.text != "lowp" && tk.text != "precise") {
        words.push_back(tk.text);
      } else if (tk.text == "[") {  // an array parameter: not traced
        words.push_back("[]");
      }
    }
    flush();
    for (auto& param : f.params)
      if (param.type == "[]") param.type = "array";
    f.bodyBegin = source.find('{', close);
    int braces = 0;
    size_t end = f.bodyBegin;
    for (std::vector<Token> all = tokenize(source, f.bodyBegin, source.size(), lineAt(source, f.bodyBegin));
         auto& tk : all) {
      braces += (tk.text == "{") - (tk.text == "}");
      if (braces == 0) {
        end = tk.end;
        break;
      }
    }
    f.bodyEnd = end;
    try {
      Parser parser(tokenize(source, f.bodyBegin, f.bodyEnd, lineAt(source, f.bodyBegin)), f);
      f.body = parser.block();
    } catch (const ParseError& e) {
      error = name + "() line " + std::to_string(e.line) + ": " + e.what();
      continue;
    }
    out = std::move(f);
    return true;
  }
  return false;
}

}  // namespace shadelab::glsl
