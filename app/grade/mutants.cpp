#include "app/grade/mutants.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

#include "app/util/format.h"

namespace shadelab {

namespace {

struct Token {
  enum class Kind { Identifier, Number, Operator, Space, Comment } kind;
  size_t at = 0, size = 0;
};

// GLSL's tokens, closely enough to find operators, literals, calls and swizzles. A preprocessor
// line is one comment: nothing in it is changed.
std::vector<Token> tokenize(const std::string& s) {
  std::vector<Token> out;
  size_t i = 0;
  bool lineStart = true;
  while (i < s.size()) {
    const size_t start = i;
    const char c = s[i];
    if (c == '\n') {
      ++i;
      out.push_back({Token::Kind::Space, start, 1});
      lineStart = true;
      continue;
    }
    if (std::isspace(static_cast<unsigned char>(c))) {
      while (i < s.size() && s[i] != '\n' && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
      out.push_back({Token::Kind::Space, start, i - start});
      continue;
    }
    if ((c == '#' && lineStart) || s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') ++i;
      out.push_back({Token::Kind::Comment, start, i - start});
      continue;
    }
    lineStart = false;
    if (s.compare(i, 2, "/*") == 0) {
      const size_t end = s.find("*/", i + 2);
      i = end == std::string::npos ? s.size() : end + 2;
      out.push_back({Token::Kind::Comment, start, i - start});
      continue;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_')) ++i;
      out.push_back({Token::Kind::Identifier, start, i - start});
      continue;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '.' ||
                              ((s[i] == '-' || s[i] == '+') && (s[i - 1] == 'e' || s[i - 1] == 'E'))))
        ++i;
      out.push_back({Token::Kind::Number, start, i - start});
      continue;
    }
    static const char* const kTwo[] = {"<=", ">=", "==", "!=", "&&", "||", "+=", "-=", "*=", "/=", "++", "--"};
    size_t n = 1;
    for (const char* op : kTwo)
      if (s.compare(i, 2, op) == 0) n = 2;
    i += n;
    out.push_back({Token::Kind::Operator, start, n});
  }
  return out;
}

struct Source {
  const std::string& text;
  std::vector<Token> tokens = tokenize(text);
  std::string of(size_t t) const { return text.substr(tokens[t].at, tokens[t].size); }
  // The previous and next tokens that are not space or comment (-1 / size() when none).
  long previous(size_t t) const {
    for (long k = long(t) - 1; k >= 0; --k)
      if (tokens[size_t(k)].kind != Token::Kind::Space && tokens[size_t(k)].kind != Token::Kind::Comment) return k;
    return -1;
  }
  size_t next(size_t t) const {
    for (size_t k = t + 1; k < tokens.size(); ++k)
      if (tokens[k].kind != Token::Kind::Space && tokens[k].kind != Token::Kind::Comment) return k;
    return tokens.size();
  }
  // Whether the token before `t` ends an operand: a binary operator follows it.
  bool afterOperand(size_t t) const {
    const long p = previous(t);
    if (p < 0) return false;
    const std::string s = of(size_t(p));
    if (tokens[size_t(p)].kind == Token::Kind::Number) return true;
    if (tokens[size_t(p)].kind == Token::Kind::Identifier) return s != "return";
    return s == ")" || s == "]";
  }
  // The matching ')' of the '(' at token `open`, and the top-level commas between.
  size_t closing(size_t open, std::vector<size_t>& commas) const {
    int depth = 0;
    for (size_t k = open; k < tokens.size(); ++k) {
      const std::string s = of(k);
      if (s == "(" || s == "[") ++depth;
      if (s == ")" || s == "]") {
        if (--depth == 0) return k;
      }
      if (s == "," && depth == 1) commas.push_back(k);
    }
    return tokens.size();
  }
  size_t end(size_t t) const { return tokens[t].at + tokens[t].size; }
};

int lineOf(const std::string& s, size_t at) {
  return 1 + int(std::count(s.begin(), s.begin() + std::ptrdiff_t(std::min(at, s.size())), '\n'));
}

std::string lineText(const std::string& s, size_t at) {
  const size_t b = s.rfind('\n', at == 0 ? 0 : at - 1), e = s.find('\n', at);
  std::string line = s.substr(b == std::string::npos ? 0 : b + 1,
                              e == std::string::npos ? std::string::npos : e - (b == std::string::npos ? 0 : b + 1));
  const size_t first = line.find_first_not_of(" \t");
  return first == std::string::npos ? "" : line.substr(first);
}

std::string doubled(const std::string& literal) {
  std::string digits = literal;
  while (!digits.empty() && (digits.back() == 'f' || digits.back() == 'F')) digits.pop_back();
  const double v = std::strtod(digits.c_str(), nullptr);
  const double w = v == 0.0 ? 1.0 : 2.0 * v;
  std::string out = formatSignificant(w);
  if (out.find_first_of(".e") == std::string::npos) out += ".0";
  return out;
}

}  // namespace

std::vector<Mutant> mutate(const std::string& region, size_t most) {
  const Source src{region};
  std::vector<Mutant> all;
  // One change: the text from `from` to `to` replaced by `with`.
  const auto add = [&](const std::string& kind, size_t from, size_t to, const std::string& with,
                       const std::string& subject = {}) {
    Mutant m;
    m.kind = kind;
    m.from = subject.empty() ? region.substr(from, to - from) : subject;
    m.to = subject.empty() ? with : subject;
    m.line = lineOf(region, from);
    m.text = region.substr(0, from) + with + region.substr(to);
    m.before = lineText(region, from);
    m.after = lineText(m.text, from);
    if (m.before != m.after) all.push_back(std::move(m));
  };
  static const std::map<std::string, std::string> kOperators{{"+", "-"},   {"-", "+"},   {"*", "/"},   {"/", "*"},
                                                             {"+=", "-="}, {"-=", "+="}, {"*=", "/="}, {"/=", "*="}};
  static const std::map<std::string, std::string> kComparisons{{"<", ">"},   {">", "<"},   {"<=", ">="}, {">=", "<="},
                                                               {"==", "!="}, {"!=", "=="}, {"&&", "||"}, {"||", "&&"}};
  // Calls whose result is a refinement of their first argument: dropping the call is a slip.
  static const std::set<std::string> kDroppable{"normalize", "max",   "min",   "clamp",    "abs",
                                                "sqrt",      "floor", "fract", "saturate", "exp"};
  // Calls whose first two arguments may be exchanged (not symmetric ones, not constructors).
  static const std::set<std::string> kSymmetric{"max",   "min",  "dot",  "vec2", "vec3",  "vec4", "ivec2", "ivec3",
                                                "ivec4", "mat2", "mat3", "mat4", "float", "int",  "bool",  "distance"};
  for (size_t t = 0; t < src.tokens.size(); ++t) {
    const Token& tok = src.tokens[t];
    const std::string s = src.of(t);
    if (tok.kind == Token::Kind::Operator) {
      if (auto it = kOperators.find(s); it != kOperators.end()) {
        if (s.size() == 2 || src.afterOperand(t)) add("operator", tok.at, src.end(t), it->second);
        if (s == "-" && !src.afterOperand(t)) add("negation-dropped", tok.at, src.end(t), "");
      }
      if (auto it = kComparisons.find(s); it != kComparisons.end()) add("comparison", tok.at, src.end(t), it->second);
      if (s == "." && src.next(t) < src.tokens.size() && src.tokens[src.next(t)].kind == Token::Kind::Identifier) {
        const size_t f = src.next(t);
        const std::string field = src.of(f);
        const bool xyzw = field.find_first_not_of("xyzw") == std::string::npos;
        const bool rgba = field.find_first_not_of("rgba") == std::string::npos;
        if ((xyzw || rgba) && field.size() <= 4) {
          const std::string set = xyzw ? "xyzw" : "rgba";
          std::string swapped = field;
          if (field.size() == 1) {
            const size_t i = set.find(field[0]);
            swapped[0] = set[i == 0 ? 1 : i - 1];
          } else {
            std::swap(swapped[0], swapped[1]);
          }
          add("swizzle", src.tokens[f].at, src.end(f), swapped);
        }
      }
    }
    if (tok.kind == Token::Kind::Number && s.find_first_of(".eE") != std::string::npos)
      add("constant", tok.at, src.end(t), doubled(s));
    if (tok.kind == Token::Kind::Identifier && src.next(t) < src.tokens.size() && src.of(src.next(t)) == "(") {
      const size_t open = src.next(t);
      std::vector<size_t> commas;
      const size_t close = src.closing(open, commas);
      if (close >= src.tokens.size()) continue;
      const size_t argsFrom = src.end(open), argsTo = src.tokens[close].at;
      if (kDroppable.count(s)) {
        const size_t firstEnd = commas.empty() ? argsTo : src.tokens[commas[0]].at;
        add("call-dropped", tok.at, src.end(close), "(" + region.substr(argsFrom, firstEnd - argsFrom) + ")", s);
      }
      if (!kSymmetric.count(s) && !commas.empty()) {
        const size_t secondEnd = commas.size() > 1 ? src.tokens[commas[1]].at : argsTo;
        std::string a = region.substr(argsFrom, src.tokens[commas[0]].at - argsFrom);
        std::string b = region.substr(src.end(commas[0]), secondEnd - src.end(commas[0]));
        const auto trim = [](std::string x) {
          const size_t f = x.find_first_not_of(" \t\n"), l = x.find_last_not_of(" \t\n");
          return f == std::string::npos ? std::string() : x.substr(f, l - f + 1);
        };
        a = trim(a);
        b = trim(b);
        if (!a.empty() && !b.empty() && a != b) add("arguments-swapped", argsFrom, secondEnd, b + ", " + a, s);
      }
    }
  }
  if (all.size() <= most) return all;
  // Spread over the kinds: one of each in turn, each kind's in the order they occur.
  std::map<std::string, std::vector<Mutant>> byKind;
  for (auto& m : all) byKind[m.kind].push_back(std::move(m));
  std::vector<Mutant> out;
  std::map<std::string, size_t> taken;
  while (out.size() < most)
    for (auto& [kind, list] : byKind)
      if (out.size() < most && taken[kind] < list.size()) out.push_back(list[taken[kind]++]);
  std::sort(out.begin(), out.end(), [](const Mutant& a, const Mutant& b) { return a.line < b.line; });
  return out;
}

std::string describeSlip(const Mutant& m, bool withFix) {
  const auto terms = [&](const std::string& what) {
    return withFix ? " (in the solution's terms, " + what + ")" : std::string();
  };
  if (m.kind == "comparison" && (m.from == "&&" || m.from == "||"))
    return "two conditions joined the other way ('and' for 'or', or the reverse)" +
           terms("a '" + m.to + "' where a '" + m.from + "' belongs");
  if (m.kind == "comparison")
    return "a comparison turned round, so the test holds where it should fail" +
           terms("a '" + m.to + "' where a '" + m.from + "' belongs");
  if (m.kind == "operator")
    return withFix
               ? "an operation turned into its inverse" + terms("a '" + m.to + "' where a '" + m.from + "' belongs")
               : "an operation turned into its inverse (an addition for a subtraction, or a product for a quotient)";
  if (m.kind == "constant") return "one constant at another value" + terms(m.to + " where " + m.from + " belongs");
  if (m.kind == "call-dropped") return "a call to " + m.from + " left out, its argument used as it is";
  if (m.kind == "arguments-swapped") return "the first two arguments of " + m.from + " exchanged";
  if (m.kind == "swizzle")
    return "one vector component read in place of another" + terms("'." + m.to + "' where '." + m.from + "' belongs");
  if (m.kind == "negation-dropped") return "a minus sign left out, so one term has the opposite sign";
  return "one change of kind " + m.kind;
}

}  // namespace shadelab
