// The trace's first half (grade/trace.h): a function instrumented with its taps.
#include "app/grade/trace.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>

#include "app/shader/glsl_syntax.h"

namespace shadelab {

namespace {

using glsl::Expr;
using glsl::Stmt;

// Built-in functions whose result is a basic type whatever their arguments (the trace taps them).
bool basicBuiltin(const std::string& f) {
  static const std::set<std::string> kNames = {"radians",
                                               "degrees",
                                               "sin",
                                               "cos",
                                               "tan",
                                               "asin",
                                               "acos",
                                               "atan",
                                               "sinh",
                                               "cosh",
                                               "tanh",
                                               "asinh",
                                               "acosh",
                                               "atanh",
                                               "pow",
                                               "exp",
                                               "log",
                                               "exp2",
                                               "log2",
                                               "sqrt",
                                               "inversesqrt",
                                               "abs",
                                               "sign",
                                               "floor",
                                               "trunc",
                                               "round",
                                               "roundEven",
                                               "ceil",
                                               "fract",
                                               "mod",
                                               "min",
                                               "max",
                                               "clamp",
                                               "mix",
                                               "step",
                                               "smoothstep",
                                               "isnan",
                                               "isinf",
                                               "floatBitsToInt",
                                               "floatBitsToUint",
                                               "intBitsToFloat",
                                               "uintBitsToFloat",
                                               "length",
                                               "distance",
                                               "dot",
                                               "cross",
                                               "normalize",
                                               "faceforward",
                                               "reflect",
                                               "refract",
                                               "lessThan",
                                               "lessThanEqual",
                                               "greaterThan",
                                               "greaterThanEqual",
                                               "equal",
                                               "notEqual",
                                               "any",
                                               "all",
                                               "not",
                                               "texture",
                                               "textureLod",
                                               "textureProj",
                                               "textureGrad",
                                               "textureOffset",
                                               "texelFetch",
                                               "textureSize",
                                               "textureLodOffset",
                                               "textureGather",
                                               "textureProjLod",
                                               "texelFetchOffset",
                                               "determinant",
                                               "dFdx",
                                               "dFdy",
                                               "fwidth",
                                               "packHalf2x16",
                                               "unpackHalf2x16",
                                               "float",
                                               "int",
                                               "uint",
                                               "bool"};
  return kNames.count(f) > 0 || glsl::isBasicType(f);
}

// Return types of the functions defined or declared in a source, by name.
std::map<std::string, std::string> functionTypes(const std::string& source) {
  std::map<std::string, std::string> out;
  static const std::regex kSignature(R"(\b([A-Za-z_]\w*)\s+([A-Za-z_]\w*)\s*\()");
  for (auto it = std::sregex_iterator(source.begin(), source.end(), kSignature); it != std::sregex_iterator(); ++it) {
    const std::string type = (*it)[1], name = (*it)[2];
    if (type == "return" || type == "else" || type == "new" || basicBuiltin(name)) continue;
    out.emplace(name, type);
  }
  return out;
}

struct Insert {
  size_t at;
  int phase;  // 0: a closing text, 1: an opening one
  int depth;  // closings: deepest first; openings: shallowest first
  std::string text;
  bool operator<(const Insert& o) const {
    if (at != o.at) return at < o.at;
    if (phase != o.phase) return phase < o.phase;
    return phase == 0 ? depth > o.depth : depth < o.depth;
  }
};

constexpr int kStatementDepth = -1000;  // a statement's own braces and taps: outside every expression

class Instrumenter {
 public:
  Instrumenter(const std::string& source, const glsl::Function& f, const std::map<std::string, std::string>& types,
               const std::set<int>& quiet, bool subExpressions, InstrumentedSource& out)
      : s_(source), f_(f), functionTypes_(types), quiet_(quiet), sub_(subExpressions), out_(out) {}

  void run() {
    for (auto& p : f_.params) types_[p.name] = p.type;
    for (auto& st : f_.stmts)
      for (auto& d : st.declared) types_[d.name] = d.type;
    // The parameters on entry (an out-parameter has no value yet).
    std::string entry;
    for (auto& p : f_.params) {
      if (p.qualifier == "out" || !glsl::isBasicType(p.type)) continue;
      const int k = point(TracePoint::Kind::Param, lineAt(f_.bodyBegin), p.name, {});
      defs_[p.name] = k;
      entry += " shadelab_tap(" + std::to_string(k) + ", " + p.name + ");";
    }
    if (!entry.empty()) inserts_.push_back({f_.bodyBegin + 1, 1, kStatementDepth, entry});
    statement(f_.body);
    if (f_.returnType == "void") {  // out-parameters as the function ends
      const std::string taps = outTaps(lineAt(f_.bodyEnd - 1));
      if (!taps.empty()) inserts_.push_back({f_.bodyEnd - 1, 1, kStatementDepth, taps});
    }
  }

  std::vector<Insert> inserts_;

 private:
  int lineAt(size_t at) const { return 1 + int(std::count(s_.begin(), s_.begin() + std::ptrdiff_t(at), '\n')); }

  int point(TracePoint::Kind kind, int line, const std::string& name, std::vector<int> from,
            const std::string& statement = "") {
    TracePoint p;
    p.kind = kind;
    p.line = line;
    p.function = f_.name;
    p.name = name;
    p.statement = statement;
    std::sort(from.begin(), from.end());
    from.erase(std::unique(from.begin(), from.end()), from.end());
    p.from = std::move(from);
    out_.points.push_back(std::move(p));
    return int(out_.points.size() - 1);
  }

  std::string tap(int k, const std::string& name) const {
    return " shadelab_tap(" + std::to_string(k) + ", " + name + ");";
  }

  std::string outTaps(int line) {
    std::string taps;
    for (auto& p : f_.params) {
      if (p.qualifier != "out" && p.qualifier != "inout") continue;
      if (!glsl::isBasicType(p.type)) continue;
      std::vector<int> from;
      if (auto it = defs_.find(p.name); it != defs_.end()) from.push_back(it->second);
      taps += tap(point(TracePoint::Kind::OutParam, line, p.name, from), p.name);
    }
    return taps;
  }

  bool basicName(const std::string& name) const {
    auto it = types_.find(name);
    return it != types_.end() && glsl::isBasicType(it->second);
  }
  bool mayBeMatrix(int e) const {
    const Expr& x = f_.exprs[e];
    if (x.kind == Expr::Kind::Name) {
      auto it = types_.find(x.text);
      return it != types_.end() && it->second.rfind("mat", 0) == 0;
    }
    if (x.kind == Expr::Kind::Call)
      return x.text.rfind("mat", 0) == 0 || x.text == "transpose" || x.text == "inverse" || x.text == "outerProduct";
    if (x.kind == Expr::Kind::Binary) return mayBeMatrix(x.args[0]) && mayBeMatrix(x.args[1]);
    return false;
  }
  bool literalOnly(int e) const {
    const Expr& x = f_.exprs[e];
    if (x.kind == Expr::Kind::Literal) return true;
    if (x.kind == Expr::Kind::Name || x.kind == Expr::Kind::Assign) return false;
    if (x.kind == Expr::Kind::Call && !glsl::isBasicType(x.text) && x.text != "float") return false;
    return std::all_of(x.args.begin(), x.args.end(), [&](int a) { return literalOnly(a); });
  }

  // Whether the value of `e` can be tapped: a basic type (as far as can be told without a compiler).
  bool tappable(int e) const {
    const Expr& x = f_.exprs[e];
    if (!sub_ || quiet_.count(x.line)) return false;
    switch (x.kind) {
      case Expr::Kind::Call: {
        if (x.arrayConstructor) return false;
        if (basicBuiltin(x.text)) return true;
        // A function of another file: its type is not known here; a struct's constructor is
        // capitalised by custom. A tap the compiler refuses is dropped by its line.
        auto it = functionTypes_.find(x.text);
        if (it == functionTypes_.end()) return std::islower(static_cast<unsigned char>(x.text[0]));
        return glsl::isBasicType(it->second);
      }
      case Expr::Kind::Binary:
        return !mayBeMatrix(x.args[0]) && !mayBeMatrix(x.args[1]);
      case Expr::Kind::Unary:
        return x.text != "++" && x.text != "--" && !mayBeMatrix(x.args[0]);
      case Expr::Kind::Ternary:
        return true;
      case Expr::Kind::Member: {  // a swizzle of a basic value
        const Expr& o = f_.exprs[x.args[0]];
        return (o.kind == Expr::Kind::Name && basicName(o.text)) || (o.kind != Expr::Kind::Name && tappable(x.args[0]));
      }
      default:
        return false;
    }
  }

  // Taps `e` and what it holds; returns the points its value is made of (its own, when tapped).
  std::vector<int> expr(int e, int depth, bool wrap, const std::string& statement = "",
                        TracePoint::Kind kind = TracePoint::Kind::Sub) {
    const Expr& x = f_.exprs[e];
    if (x.kind == Expr::Kind::Literal) {
      std::string t = x.text;
      while (!t.empty() && (t.back() == 'u' || t.back() == 'U' || t.back() == 'f' || t.back() == 'F')) t.pop_back();
      char* end = nullptr;
      const double v = std::strtod(t.c_str(), &end);
      if (end && *end == '\0' && !t.empty()) out_.literals.push_back(v);
      if (kind != TracePoint::Kind::Returned) return {};
    }
    if (x.kind == Expr::Kind::Name && kind != TracePoint::Kind::Returned) {
      auto it = defs_.find(x.text);
      return it == defs_.end() ? std::vector<int>{} : std::vector<int>{it->second};
    }
    std::vector<int> from;
    const bool own = wrap && (kind == TracePoint::Kind::Returned || tappable(e));
    if (x.kind != Expr::Kind::Name)
      for (size_t a = 0; a < x.args.size(); ++a) {
        if (x.kind == Expr::Kind::Assign && a == 0) continue;  // a target is written, not read
        const std::vector<int> got = expr(x.args[a], depth + 1, wrap);
        from.insert(from.end(), got.begin(), got.end());
      }
    else if (auto it = defs_.find(x.text); it != defs_.end())
      from.push_back(it->second);
    if (!own) return from;
    const int k = point(kind, x.line, glsl::exprText(s_, x), from, statement);
    out_.points[k].constant = literalOnly(e);
    inserts_.push_back({x.begin, 1, depth, "shadelab_tap(" + std::to_string(k) + ", "});
    inserts_.push_back({x.end, 0, depth, ")"});
    return {k};
  }

  // The variable an assignment's target writes: `x` of x, x.y, x[i].
  std::string root(int e) const {
    const Expr* x = &f_.exprs[e];
    while (x->kind == Expr::Kind::Member || x->kind == Expr::Kind::Index) x = &f_.exprs[x->args[0]];
    return x->kind == Expr::Kind::Name ? x->text : "";
  }

  // The variable's point after the statement that sets it, or -1 for one the taps cannot take.
  int assigned(const Stmt& st, const std::string& var, std::vector<int> from) {
    if (var.empty() || !basicName(var)) return -1;
    const int k = point(TracePoint::Kind::Assigned, st.line, var, std::move(from), var);
    defs_[var] = k;
    inserts_.push_back({st.begin, 1, kStatementDepth, "{ "});
    inserts_.push_back({st.end, 0, kStatementDepth, tap(k, var) + " }"});
    return k;
  }

  void statement(int index) {
    const Stmt& st = f_.stmts[index];
    switch (st.kind) {
      case Stmt::Kind::Block:
        for (int b : st.body) statement(b);
        break;
      case Stmt::Kind::Declaration: {
        std::string taps;
        for (auto& d : st.declared) {
          std::vector<int> from;
          if (d.init >= 0) from = expr(d.init, 0, !d.constant, d.name);
          if (!glsl::isBasicType(d.type)) continue;
          const int k = point(TracePoint::Kind::Declared, st.line, d.name, from, d.name);
          out_.points[k].constant = d.init >= 0 && literalOnly(d.init);
          out_.points[k].initialised = d.init >= 0;
          defs_[d.name] = k;
          taps += tap(k, d.name);
        }
        if (!taps.empty()) inserts_.push_back({st.end, 0, kStatementDepth, taps});
        break;
      }
      case Stmt::Kind::Expression: {
        const Expr& x = f_.exprs[st.expr];
        if (x.kind == Expr::Kind::Assign) {
          const std::string var = root(x.args[0]);
          std::vector<int> from = expr(x.args[1], 0, true, var);
          const bool readsTarget = x.text != "=" || f_.exprs[x.args[0]].kind != Expr::Kind::Name;
          if (auto it = defs_.find(var); readsTarget && it != defs_.end()) from.push_back(it->second);
          if (const int k = assigned(st, var, std::move(from)); k >= 0)
            out_.points[size_t(k)].constant = !readsTarget && literalOnly(x.args[1]);
        } else if ((x.kind == Expr::Kind::Postfix || x.kind == Expr::Kind::Unary) &&
                   (x.text == "++" || x.text == "--")) {
          const std::string var = root(x.args[0]);
          std::vector<int> from;
          if (auto it = defs_.find(var); it != defs_.end()) from.push_back(it->second);
          assigned(st, var, std::move(from));
        } else if (x.kind == Expr::Kind::Call) {  // a call for its out-arguments: tap each variable passed
          std::vector<int> from;
          for (int a : x.args) {
            const std::vector<int> got = expr(a, 1, true);
            from.insert(from.end(), got.begin(), got.end());
          }
          for (int a : x.args)
            if (f_.exprs[a].kind == Expr::Kind::Name && basicName(f_.exprs[a].text) && defs_.count(f_.exprs[a].text) &&
                out_.points[defs_[f_.exprs[a].text]].kind != TracePoint::Kind::Param)
              assigned(st, f_.exprs[a].text, from);
        } else {
          expr(st.expr, 0, true);
        }
        break;
      }
      case Stmt::Kind::Return: {
        const std::string outs = outTaps(st.line);
        if (st.expr >= 0) {
          if (glsl::isBasicType(f_.returnType))
            expr(st.expr, 0, true, "return", TracePoint::Kind::Returned);
          else
            for (int k : expr(st.expr, 0, true)) out_.points[size_t(k)].partOfResult = true;
        }
        if (!outs.empty()) {
          inserts_.push_back({st.begin, 1, kStatementDepth, "{" + outs + " "});
          inserts_.push_back({st.end, 0, kStatementDepth, " }"});
        }
        break;
      }
      case Stmt::Kind::If:
      case Stmt::Kind::While:
      case Stmt::Kind::Do:
        if (st.expr >= 0) expr(st.expr, 0, true);
        for (int b : st.body) statement(b);
        break;
      case Stmt::Kind::For:
        for (int b : st.body) statement(b);
        break;
      default:
        break;
    }
  }

  const std::string& s_;
  const glsl::Function& f_;
  const std::map<std::string, std::string>& functionTypes_;
  const std::set<int>& quiet_;
  bool sub_;
  InstrumentedSource& out_;
  std::map<std::string, std::string> types_;
  std::map<std::string, int> defs_;
};

}  // namespace

std::string tapOverloads(const std::string& write) {
  // Each type's value as the vec4 written: xyz and, in w, the component count.
  static const std::pair<const char*, const char*> kTypes[] = {{"float", "vec4(v, 0.0, 0.0, 1.0)"},
                                                               {"vec2", "vec4(v, 0.0, 2.0)"},
                                                               {"vec3", "vec4(v, 3.0)"},
                                                               {"vec4", "vec4(v.xyz, 4.0)"},
                                                               {"int", "vec4(float(v), 0.0, 0.0, 1.0)"},
                                                               {"ivec2", "vec4(vec2(v), 0.0, 2.0)"},
                                                               {"ivec3", "vec4(vec3(v), 3.0)"},
                                                               {"ivec4", "vec4(vec3(v.xyz), 4.0)"},
                                                               {"uint", "vec4(float(v), 0.0, 0.0, 1.0)"},
                                                               {"bool", "vec4(v ? 1.0 : 0.0, 0.0, 0.0, 1.0)"},
                                                               {"bvec2", "vec4(vec2(v), 0.0, 2.0)"},
                                                               {"bvec3", "vec4(vec3(v), 3.0)"},
                                                               {"bvec4", "vec4(vec3(v.xyz), 4.0)"}};
  std::string out;
  for (auto& [type, value] : kTypes)
    out += std::string(type) + " shadelab_tap(int k, " + type + " v) { " + write + "(k, " + value + "); return v; }\n";
  for (const char* type : {"mat2", "mat3", "mat4"})  // not written out: a tap that only passes the value on
    out += std::string(type) + " shadelab_tap(int k, " + type + " v) { return v; }\n";
  return out;
}

const std::string& tracePrelude() {
  static const std::string prelude =
      "// The trace's taps (grade/trace.h): each returns its value and writes it out when it is the point traced.\n"
      "uniform int shadelab_trace;\n"
      "vec4 shadelab_traced = vec4(0.0);\n"
      "void shadelab_write(int k, vec4 v) { if (k == shadelab_trace) shadelab_traced = v; }\n" +
      tapOverloads("shadelab_write");
  return prelude;
}

InstrumentedSource instrumentFunctions(const std::string& source, const std::vector<std::string>& functions,
                                       const std::vector<int>& quietLines, bool subExpressions,
                                       bool derivativesAllowed) {
  InstrumentedSource out;
  const std::map<std::string, std::string> types = functionTypes(source);
  const std::set<int> quiet(quietLines.begin(), quietLines.end());
  std::vector<Insert> inserts;
  for (auto& name : functions) {
    glsl::Function f;
    std::string error;
    if (!glsl::parseFunction(source, name, f, error)) {
      out.error = error;
      return out;
    }
    for (auto& x : f.exprs)
      if (!derivativesAllowed && x.kind == Expr::Kind::Call &&
          (x.text == "dFdx" || x.text == "dFdy" || x.text == "fwidth")) {
        out.error = name + "() takes derivatives (" + x.text + "): its values mean something only in the lab's draw";
        return out;
      }
    Instrumenter in(source, f, types, quiet, subExpressions, out);
    in.run();
    inserts.insert(inserts.end(), in.inserts_.begin(), in.inserts_.end());
  }
  std::stable_sort(inserts.begin(), inserts.end());
  out.text.reserve(source.size() + inserts.size() * 24);
  size_t at = 0;
  for (auto& i : inserts) {
    out.text.append(source, at, i.at - at);
    out.text += i.text;
    at = i.at;
  }
  out.text.append(source, at, std::string::npos);
  return out;
}

}  // namespace shadelab
