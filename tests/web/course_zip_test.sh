#!/usr/bin/env bash
# The page's course-zip reader (web/course.js) on zips made to break it, in Node (the same
# DecompressionStream as the browser's): a zip of a course folder unpacks under /courses/NAME with
# its folder found; a name that leaves the folder, an entry that inflates past its declared size,
# a truncated archive, a file that is not a zip, an encrypted entry and a zip with no rubric are
# each refused with one line naming the zip, and nothing is written for them.
# usage: course_zip_test.sh REPO OUT_DIR
set -euo pipefail
repo=$1 out=$2
command -v node >/dev/null || { echo "node is not installed (./web.sh installs emscripten, which brings it)"; exit 77; }
mkdir -p "$out"
python3 - "$repo/tests/data/course" "$out" <<'PY'
import io, os, struct, sys, zipfile
course, out = sys.argv[1:]
def write(name, entries, method=zipfile.ZIP_DEFLATED):
    with zipfile.ZipFile(os.path.join(out, name), "w", method) as z:
        for path, data in entries:
            z.writestr(path, data)
files = []
for folder, _, names in os.walk(course):
    for n in names:
        p = os.path.join(folder, n)
        files.append(("week3/" + os.path.relpath(p, course), open(p, "rb").read()))
write("week3.zip", files + [("__MACOSX/week3/._rubric.json", b"x")])
write("stored.zip", [(p[len("week3/"):], d) for p, d in files], zipfile.ZIP_STORED)
write("escape.zip", files + [("week3/../../student/x.glsl", b"overwritten")])
write("norubric.zip", [("week3/shading/notes.md", b"no exercise here")])
# An entry that inflates far past the size its directory declares.
write("bomb.zip", [("week3/shading/a/rubric.json", b"\0" * (1 << 20))])
data = bytearray(open(os.path.join(out, "bomb.zip"), "rb").read())
at = data.rfind(b"PK\x01\x02")
data[at + 24:at + 28] = struct.pack("<I", 100)
open(os.path.join(out, "bomb.zip"), "wb").write(bytes(data))
whole = open(os.path.join(out, "week3.zip"), "rb").read()
open(os.path.join(out, "truncated.zip"), "wb").write(whole[: len(whole) // 2] + whole[-22:])
open(os.path.join(out, "notazip.zip"), "wb").write(b"just text")
# The encryption flag set on an entry (bit 0 of the general-purpose flags).
data = bytearray(whole)
at = data.find(b"PK\x01\x02")
data[at + 8] |= 1
open(os.path.join(out, "encrypted.zip"), "wb").write(bytes(data))
PY
node - "$repo/web/course.js" "$out" <<'JS'
const fs = require('fs'), path = require('path');
const [source, out] = process.argv.slice(2);
const ShadeLabCourse = new Function(fs.readFileSync(source, 'utf8') + '\nreturn ShadeLabCourse;')();
// The page's file system, in memory: what unpack() writes.
const files = new Map(), dirs = new Set(['/courses']);
const FS = {
  analyzePath: (p) => ({ exists: dirs.has(p) || files.has(p) }),
  readdir: (p) => ['.', '..', ...new Set([...files.keys(), ...dirs].filter((f) => path.dirname(f) === p).map((f) => path.basename(f)))],
  stat: (p) => ({ mode: dirs.has(p) ? 1 : 0 }),
  isDir: (mode) => mode === 1,
  unlink: (p) => files.delete(p),
  rmdir: (p) => dirs.delete(p),
  mkdirTree: (p) => { for (let d = p; d !== '/'; d = path.dirname(d)) dirs.add(d); },
  writeFile: (p, bytes) => files.set(p, bytes),
};
const expect = {
  'week3.zip': /^\/courses\/week3$/,
  'stored.zip': /^\/courses\/stored$/,
  'escape.zip': /^escape\.zip: 'week3\/\.\.\/\.\.\/student\/x\.glsl' leaves the course's folder/,
  'norubric.zip': /^norubric\.zip holds no exercise/,
  'bomb.zip': /^bomb\.zip: week3\/shading\/a\/rubric\.json unpacks to more than the 100 bytes its header declares/,
  'truncated.zip': /^truncated\.zip: /,
  'notazip.zip': /^notazip\.zip: not a zip archive/,
  'encrypted.zip': /^encrypted\.zip: .* is encrypted/,
};
(async () => {
  let failed = 0;
  for (const [name, want] of Object.entries(expect)) {
    const before = files.size;
    let got;
    try {
      const bytes = fs.readFileSync(path.join(out, name));  // its own ArrayBuffer: Node pools small files
      got = await ShadeLabCourse.unpack(FS, bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.length), name);
    } catch (e) {
      got = String(e);
      if (files.size !== before) { console.log(`${name}: refused, but ${files.size - before} files were written`); failed++; }
    }
    const ok = want.test(got);
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}: ${got}`);
    failed += !ok;
  }
  for (const f of ['/courses/week3/shading/point-lights/rubric.json',
                   '/courses/week3/shading/point-lights/starter/common/lighting.glsl.part',
                   '/courses/stored/shading/specular-lobe/rubric.json'])
    if (!files.has(f)) { console.log(`FAIL ${f} was not written`); failed++; }
  if ([...files.keys()].some((f) => f.includes('MACOSX') || !f.startsWith('/courses/'))) {
    console.log('FAIL something was written outside /courses or from __MACOSX'); failed++;
  }
  console.log(failed ? `course zips: ${failed} failed` : 'course zips: every case as expected');
  process.exit(failed ? 1 : 0);
})();
JS
