#include "app/grade/trace.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <set>

#include <nlohmann/json.hpp>

#include "app/shader/glsl_syntax.h"
#include "app/util/format.h"

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
            expr(st.expr, 0, true);
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

const char* tracePrelude() {
  return R"(// The trace's taps (grade/trace.h): each returns its value and writes it out when it is the point traced.
uniform int shadelab_trace;
vec4 shadelab_traced = vec4(0.0);
float shadelab_tap(int k, float v) { if (k == shadelab_trace) shadelab_traced = vec4(v, 0.0, 0.0, 1.0); return v; }
vec2 shadelab_tap(int k, vec2 v) { if (k == shadelab_trace) shadelab_traced = vec4(v, 0.0, 2.0); return v; }
vec3 shadelab_tap(int k, vec3 v) { if (k == shadelab_trace) shadelab_traced = vec4(v, 3.0); return v; }
vec4 shadelab_tap(int k, vec4 v) { if (k == shadelab_trace) shadelab_traced = vec4(v.xyz, 4.0); return v; }
int shadelab_tap(int k, int v) { if (k == shadelab_trace) shadelab_traced = vec4(float(v), 0.0, 0.0, 1.0); return v; }
ivec2 shadelab_tap(int k, ivec2 v) { if (k == shadelab_trace) shadelab_traced = vec4(vec2(v), 0.0, 2.0); return v; }
ivec3 shadelab_tap(int k, ivec3 v) { if (k == shadelab_trace) shadelab_traced = vec4(vec3(v), 3.0); return v; }
ivec4 shadelab_tap(int k, ivec4 v) { if (k == shadelab_trace) shadelab_traced = vec4(vec3(v.xyz), 4.0); return v; }
uint shadelab_tap(int k, uint v) { if (k == shadelab_trace) shadelab_traced = vec4(float(v), 0.0, 0.0, 1.0); return v; }
bool shadelab_tap(int k, bool v) { if (k == shadelab_trace) shadelab_traced = vec4(v ? 1.0 : 0.0, 0.0, 0.0, 1.0); return v; }
bvec2 shadelab_tap(int k, bvec2 v) { if (k == shadelab_trace) shadelab_traced = vec4(vec2(v), 0.0, 2.0); return v; }
bvec3 shadelab_tap(int k, bvec3 v) { if (k == shadelab_trace) shadelab_traced = vec4(vec3(v), 3.0); return v; }
bvec4 shadelab_tap(int k, bvec4 v) { if (k == shadelab_trace) shadelab_traced = vec4(vec3(v.xyz), 4.0); return v; }
mat2 shadelab_tap(int k, mat2 v) { return v; }
mat3 shadelab_tap(int k, mat3 v) { return v; }
mat4 shadelab_tap(int k, mat4 v) { return v; }
)";
}

InstrumentedSource instrumentFunctions(const std::string& source, const std::vector<std::string>& functions,
                                       const std::vector<int>& quietLines, bool subExpressions) {
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
      if (x.kind == Expr::Kind::Call && (x.text == "dFdx" || x.text == "dFdy" || x.text == "fwidth")) {
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

// ---------------------------------------------------------------------------------------------
// Alignment

namespace {

constexpr int kFewestRows = 8;          // rows both sides must reach before their values say anything
constexpr double kMatchingRows = 0.98;  // the share of those rows that must agree (a kink's neighbours may not)

bool close(float a, float b) {
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  if (std::isinf(a) || std::isinf(b)) return a == b;
  return std::abs(a - b) <= 1e-5 + 3e-4 * std::max(std::abs(a), std::abs(b));
}

int componentsAt(const std::vector<glm::vec4>& v) {
  int n = 0;
  for (auto& x : v) n = std::max(n, std::min(3, int(x.w)));
  return n;
}

// Whether component `ca` of `a` is, row by row, f(component `cb` of `b`), on the rows `a` reached:
// `b` must have been reached on them too (a value of one branch of the solution's, reached on a
// third of the rows, says nothing of the other two).
template <typename F>
bool follows(const std::vector<glm::vec4>& a, int ca, const std::vector<glm::vec4>& b, int cb, F f) {
  size_t mine = 0, both = 0, agree = 0;
  for (size_t r = 0; r < a.size() && r < b.size(); ++r) {
    if (a[r].w <= 0.0f) continue;
    ++mine;
    if (b[r].w <= 0.0f) continue;
    ++both;
    agree += close(a[r][ca], f(b[r][cb]));
  }
  return both >= size_t(kFewestRows) && double(both) >= kMatchingRows * double(mine) &&
         double(agree) >= kMatchingRows * double(both);
}

bool reached(const std::vector<glm::vec4>& v) {
  return std::count_if(v.begin(), v.end(), [](const glm::vec4& x) { return x.w > 0.0f; }) >= kFewestRows;
}

// The value of component c on every row it was reached, if it is one constant.
bool constantValue(const std::vector<glm::vec4>& v, int c, float& value) {
  bool first = true;
  for (auto& x : v) {
    if (x.w <= 0.0f) continue;
    if (first) {
      value = x[c];
      first = false;
    } else if (!close(x[c], value)) {
      return false;
    }
  }
  return !first;
}

class Aligner {
 public:
  Aligner(const TraceValues& student, const TraceValues& solution) : st_(student), so_(solution) {}

  // Whether the student's point k is a value the solution computes: a scalar, any of its values'
  // components; a vector, one of its vectors whole, component for component (x and y exchanged
  // is another value; a 0.0 or 1.0 written into it stands for itself).
  bool matches(int k) {
    if (auto it = memo_.find(k); it != memo_.end()) return it->second;
    const auto& a = st_.values[k];
    const int n = componentsAt(a);
    // What no input reaches (a literal, a texture's size, a product of uniforms) can be told
    // wrong only against a value of the solution's that no input reaches either; where the
    // solution has none of its size, it is given, like a uniform. A value the inputs reach that
    // comes out constant (a channel the map does not hold) must be the solution's like any other.
    if (!readsInputs(k) && !solutionHasInputFree(n)) return memo_[k] = true;
    bool found = n == 1 && componentMatches(a, 0, !readsInputs(k));
    for (size_t q = 0; n > 1 && q < so_.values.size() && !found; ++q) {
      const auto& b = so_.values[q];
      if (componentsAt(b) != n) continue;
      bool all = true;
      for (int c = 0; c < n && all; ++c) all = constantMatches(a, c) || follows(a, c, b, c, [](float x) { return x; });
      found = all;
    }
    return memo_[k] = found;
  }
  // Whether the solution computes a value of n components that no input reaches.
  bool solutionHasInputFree(int n) const {
    for (size_t q = 0; q < so_.points.size(); ++q)
      if (so_.points[q].kind != TracePoint::Kind::Param && componentsAt(so_.values[q]) == n &&
          !readsInputs(so_, q, solutionReads_))
        return true;
    return false;
  }
  bool readsInputs(int k) { return readsInputs(st_, size_t(k), reads_); }
  static bool readsInputs(const TraceValues& side, size_t k, std::map<size_t, bool>& memo) {
    if (auto it = memo.find(k); it != memo.end()) return it->second;
    memo[k] = false;  // a loop's value reads itself
    const TracePoint& p = side.points[k];
    bool reads = p.kind == TracePoint::Kind::Param;
    for (int q : p.from) reads = reads || readsInputs(side, size_t(q), memo);
    return memo[k] = reads;
  }
  static bool isConstant(const std::vector<glm::vec4>& a, int c) {
    float value = 0.0f;
    return constantValue(a, c, value);
  }
  // Whether each component of point k is somewhere among the solution's values (in any place):
  // a value made of the solution's, rearranged, rather than one it never computes.
  bool componentsFound(int k) {
    const auto& a = st_.values[k];
    const int n = componentsAt(a);
    bool all = n > 0;
    for (int c = 0; c < n && all; ++c) all = componentMatches(a, c, true);
    return all;
  }
  bool reachedPoint(int k) const { return reached(st_.values[k]); }

 private:
  // A component constant over every row reached, at 0, 1 or a number the solution writes.
  bool constantMatches(const std::vector<glm::vec4>& a, int c) const {
    float value = 0.0f;
    if (!constantValue(a, c, value)) return false;
    if (close(value, 0.0f) || close(value, 1.0f)) return true;
    for (double l : so_.literals)
      if (close(value, float(l))) return true;
    return false;
  }
  bool componentMatches(const std::vector<glm::vec4>& a, int c, bool constantsCount) {
    if (constantsCount && constantMatches(a, c)) return true;
    // A constant is told apart only by a value of the solution's that is one number too: a
    // vector's constant component (the green of a one-channel map) says nothing.
    float value = 0.0f;
    const bool constant = constantValue(a, c, value);
    for (size_t q = 0; q < so_.values.size(); ++q) {
      const auto& b = so_.values[q];
      const int m = componentsAt(b);
      if (constant && m != 1) continue;
      for (int cb = 0; cb < m; ++cb)
        if (follows(a, c, b, cb, [](float x) { return x; })) return true;
    }
    for (auto& q : so_.quantities) {
      if (constant) break;
      std::vector<glm::vec4> b(q.size());
      for (size_t r = 0; r < q.size(); ++r) b[r] = {q[r], 0.0f, 0.0f, 1.0f};
      if (follows(a, c, b, 0, [](float x) { return x; }) || follows(a, c, b, 0, [](float x) { return 1.0f / x; }) ||
          follows(a, c, b, 0, [](float x) { return x * x; }) ||
          follows(a, c, b, 0, [](float x) { return 1.0f / (x * x); }) ||
          follows(a, c, b, 0, [](float x) { return x >= 0.0f ? std::sqrt(x) : std::nanf(""); }))
        return true;
    }
    return false;
  }

  const TraceValues& st_;
  const TraceValues& so_;
  std::map<int, bool> memo_;
  std::map<size_t, bool> reads_;
  mutable std::map<size_t, bool> solutionReads_;
};

// How `a` relates to `b` (same component count), in words: "" when no simple relation fits.
std::string relationTo(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b, const std::string& what) {
  const int n = componentsAt(a);
  if (n == 0 || componentsAt(b) != n) return "";
  const auto all = [&](auto f) {
    for (int c = 0; c < n; ++c)
      if (!follows(a, c, b, c, f)) return false;
    return true;
  };
  if (all([](float x) { return -x; })) return what + ", negated";
  if (all([](float x) { return 1.0f - x; })) return "one minus " + what;
  if (all([](float x) { return x * x; })) return what + ", squared";
  if (all([](float x) { return x >= 0.0f ? std::sqrt(x) : std::nanf(""); })) return "the square root of " + what;
  if (all([](float x) { return 1.0f / x; })) return "one over " + what;
  // A constant factor: fitted on the rows where b is far from zero, then checked on every row.
  double num = 0.0, den = 0.0;
  for (size_t r = 0; r < a.size() && r < b.size(); ++r)
    for (int c = 0; c < n; ++c)
      if (a[r].w > 0.0f && b[r].w > 0.0f && std::isfinite(a[r][c]) && std::isfinite(b[r][c])) {
        num += double(a[r][c]) * b[r][c];
        den += double(b[r][c]) * b[r][c];
      }
  if (den > 1e-12) {
    const float k = float(num / den);
    if (std::abs(k - 1.0f) > 1e-3f && std::abs(k) > 1e-4f && all([k](float x) { return k * x; }))
      return formatNumber(std::round(k * 1000.0) / 1000.0) + " times " + what;
  }
  // A constant offset.
  double sum = 0.0;
  size_t count = 0;
  for (size_t r = 0; r < a.size() && r < b.size(); ++r)
    if (a[r].w > 0.0f && b[r].w > 0.0f && std::isfinite(a[r][0]) && std::isfinite(b[r][0])) {
      sum += double(a[r][0]) - b[r][0];
      ++count;
    }
  if (count > 0) {
    const float d = float(sum / double(count));
    if (std::abs(d) > 1e-4f && all([d](float x) { return x + d; }))
      return what + (d > 0 ? " plus " : " minus ") + formatNumber(std::round(std::abs(d) * 10000.0) / 10000.0);
  }
  return "";
}

// Whether `a` holds the components of `b` in another order: "x and y exchanged", or "".
std::string rearranged(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  const int n = componentsAt(a);
  if (n < 2 || componentsAt(b) != n) return "";
  int from[3] = {-1, -1, -1};
  bool moved = false;
  for (int c = 0; c < n; ++c) {
    for (int d = 0; d < n && from[c] < 0; ++d)
      if (follows(a, c, b, d, [](float x) { return x; })) from[c] = d;
    if (from[c] < 0) return "";
    moved |= from[c] != c;
  }
  if (!moved) return "";
  std::string moves;
  for (int c = 0; c < n; ++c)
    if (from[c] != c && from[c] > c && from[from[c]] == c)
      moves += std::string(moves.empty() ? "" : ", ") + "xyz"[c] + " and " + "xyz"[from[c]] + " exchanged";
  if (moves.empty())
    for (int c = 0; c < n; ++c)
      if (from[c] != c) moves += std::string(moves.empty() ? "" : ", ") + "xyz"[c] + " holding " + "xyz"[from[c]];
  return moves;
}

std::string quotedNames(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i)
    out += (i == 0 ? "" : i + 1 == names.size() ? " and " : ", ") + ("`" + names[i] + "`");
  return out;
}

}  // namespace

TraceFinding alignTraces(const TraceValues& student, const TraceValues& solution,
                         const std::vector<std::pair<std::string, std::string>>& inputs, const std::string& file) {
  TraceFinding out;
  Aligner align(student, solution);
  const auto wrong = [&](int k) { return align.reachedPoint(k) && !align.matches(k); };
  // Where to start: the student's results that differ from the solution's result.
  int solutionResult = -1;
  for (size_t k = 0; k < solution.points.size(); ++k)
    if (solution.points[k].kind == TracePoint::Kind::Returned && reached(solution.values[k])) solutionResult = int(k);
  int departure = -1;
  for (size_t k = 0; k < student.points.size(); ++k) {
    const TracePoint::Kind kind = student.points[k].kind;
    if (kind != TracePoint::Kind::Returned && kind != TracePoint::Kind::OutParam) continue;
    if (!wrong(int(k))) continue;
    // Down through what it is made of, always into the earliest value that is wrong.
    int at = int(k);
    std::set<int> seen;
    for (;;) {
      seen.insert(at);
      // A value the solution never computes before one that only rearranges the solution's values.
      int next = -1;
      bool nextNovel = false;
      for (int q : student.points[at].from) {
        if (seen.count(q) || !wrong(q)) continue;
        const bool novel = !align.componentsFound(q);
        if (next < 0 || (novel && !nextNovel) ||
            (novel == nextNovel && student.points[q].line < student.points[next].line)) {
          next = q;
          nextNovel = novel;
        }
      }
      if (next < 0) break;
      at = next;
    }
    if (departure < 0 || student.points[at].line < student.points[departure].line) departure = at;
  }
  if (departure < 0) return out;
  const TracePoint& p = student.points[departure];
  out.found = true;
  out.line = p.line;
  out.function = p.function;
  // A statement's whole value is named by its variable.
  out.name =
      (p.kind == TracePoint::Kind::Sub && !p.statement.empty() && p.statement != "return") ? p.statement : p.name;
  for (int q : p.from) {
    const TracePoint& o = student.points[q];
    if (align.reachedPoint(q) && !o.constant && align.matches(q)) out.matching.push_back(o.name);
  }
  std::sort(out.matching.begin(), out.matching.end());
  out.matching.erase(std::unique(out.matching.begin(), out.matching.end()), out.matching.end());
  // "Up to here" only where it is so: every value the student computes on earlier lines matches.
  bool earlierMatch = true;
  for (size_t k = 0; k < student.points.size(); ++k) {
    const TracePoint& o = student.points[k];
    if (o.function != p.function || o.line >= p.line || !align.reachedPoint(int(k)) || o.constant) continue;
    if (align.matches(int(k)))
      ++out.matchedBefore;
    else
      earlierMatch = false;
  }
  if (solutionResult >= 0)
    out.relation = relationTo(student.values[departure], solution.values[solutionResult], "the solution's result");
  // How it relates to an input it is not written from (of one it is, the code itself says as much).
  std::set<std::string> readsDirectly;
  for (int q : p.from) readsDirectly.insert(student.points[q].name);
  if (out.relation.empty())
    for (auto& [name, says] : inputs)
      for (size_t q = 0; q < solution.points.size() && out.relation.empty() && !readsDirectly.count(name); ++q)
        if (solution.points[q].kind == TracePoint::Kind::Param && solution.points[q].name == name)
          out.relation = relationTo(student.values[departure], solution.values[q], says);
  // A value of the solution's with its components in another order.
  for (size_t q = 0; q < solution.points.size() && out.relation.empty(); ++q)
    if (const std::string moves = rearranged(student.values[departure], solution.values[q]); !moves.empty())
      out.relation = "one of the solution's values with its components in another order (" + moves + ")";
  // The sentence: the line, what matches up to it, and what its value is; never the solution's code.
  std::string t = "Line " + std::to_string(p.line) + " of " + file + " (`" + out.name + "`): ";
  if (earlierMatch && out.matchedBefore > 0) t += "your values up to this line match the solution's; here ";
  t += (p.kind == TracePoint::Kind::Returned ? "what " + p.function + "() returns" : "`" + out.name + "`") +
       " takes values that none of the solution's steps take";
  if (!out.matching.empty())
    t += ", though " + quotedNames(out.matching) + ", which it is made of, " +
         (out.matching.size() == 1 ? "matches" : "match") + " the solution's values";
  t += ".";
  if (!out.relation.empty()) t += " It is " + out.relation + ".";
  out.text = t;
  return out;
}

nlohmann::json toJson(const TraceFinding& f) {
  return {{"found", f.found},
          {"line", f.line},
          {"name", f.name},
          {"function", f.function},
          {"matching", f.matching},
          {"relation", f.relation},
          {"matched_before", f.matchedBefore},
          {"text", f.text}};
}

TraceFinding traceFindingFromJson(const nlohmann::json& j) {
  TraceFinding f;
  if (!j.is_object()) return f;
  f.found = j.value("found", false);
  f.line = j.value("line", 0);
  f.name = j.value("name", std::string());
  f.function = j.value("function", std::string());
  if (j.contains("matching") && j["matching"].is_array())
    for (auto& m : j["matching"])
      if (m.is_string()) f.matching.push_back(m.get<std::string>());
  f.relation = j.value("relation", std::string());
  f.matchedBefore = j.value("matched_before", 0);
  f.text = j.value("text", std::string());
  return f;
}

}  // namespace shadelab
