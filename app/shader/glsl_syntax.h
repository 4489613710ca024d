// A GLSL function read as a tree: its signature, its statements and every expression in them, each
// with where it lies in the source (byte offsets and a 1-based line). Enough of the language to
// trace a student's function value by value (grade/trace.h): declarations, assignments, returns,
// if / for / while / do, blocks, and expressions with GLSL's precedence. Types are not checked and
// names are not resolved: that is the compiler's work, and a function it accepts reads here too.
// Preprocessor lines inside a body (#ifdef ... #else ... #endif) are skipped, so both branches are
// read, one after the other; the compiler keeps one of them.
//
// Pure text work, unit-tested without a context (tests/unit/trace_test.cpp).
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace shadelab::glsl {

struct Expr {
  enum class Kind {
    Literal,   // 1.0, 2, true
    Name,      // N, u_bias
    Call,      // dot(N, L), vec3(1.0), float[3](...): `text` is the callee, `args` its arguments
    Member,    // v.xy, light.position: `text` is the member, args[0] the object
    Index,     // taps[i]: args[0] the array, args[1] the index
    Unary,     // -x, !b, ++i (prefix): `text` the operator
    Postfix,   // i++: `text` the operator
    Binary,    // a * b, a < b, a && b: `text` the operator
    Ternary,   // c ? a : b
    Assign,    // x = e, x += e: `text` the operator, args[0] the target, args[1] the value
    Sequence,  // a, b (the comma operator)
  };
  Kind kind = Kind::Literal;
  std::string text;
  std::vector<int> args;      // indices into Function::exprs
  size_t begin = 0, end = 0;  // [begin, end) in the source
  int line = 0;
  bool arrayConstructor = false;  // float[3](...)
};

struct Declarator {
  std::string type;  // "vec3", "float[4]" (a name's own brackets included)
  std::string name;
  int init = -1;  // the initialiser's expression, or -1
  bool constant = false;
};

struct Stmt {
  enum class Kind { Block, Declaration, Expression, Return, If, For, While, Do, Jump, Empty };
  Kind kind = Kind::Empty;
  size_t begin = 0, end = 0;  // [begin, end): from its first token to just past its ';' or '}'
  int line = 0;
  int expr = -1;                     // Expression, Return (or -1), If / While / Do: the condition
  std::vector<int> body;             // Block: its statements; If: then [, else]; For / While / Do: the body
  std::vector<Declarator> declared;  // Declaration
  // For: the loop's header, never traced (its init, condition and step are the loop's bookkeeping).
  size_t headerBegin = 0, headerEnd = 0;
};

struct Param {
  std::string qualifier;  // "", "in", "out", "inout" (precision and const dropped)
  std::string type, name;
};

struct Function {
  std::string returnType, name;
  std::vector<Param> params;
  size_t begin = 0;      // the return type's first character
  size_t bodyBegin = 0;  // the opening brace
  size_t bodyEnd = 0;    // just past the closing brace
  int body = -1;         // the body's Block statement
  std::vector<Expr> exprs;
  std::vector<Stmt> stmts;
};

// The definition of `name` in `source` (the first one whose body parses). False, with `error` saying
// where and why, when there is none or its body is outside what this reads.
bool parseFunction(std::string_view source, const std::string& name, Function& out, std::string& error);

// The text of an expression as written (whitespace runs folded to one space).
std::string exprText(std::string_view source, const Expr& e);

// GLSL's basic types, whose values a trace can write out: float, int, uint, bool and their vectors.
bool isBasicType(const std::string& type);
// The number of components of a basic type (float 1 ... vec4 4); 0 for any other type.
int componentsOf(const std::string& type);

}  // namespace shadelab::glsl
