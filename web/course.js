// A course in a zip, opened by the page itself: by link (index.html#course=week3.zip, a file of the
// same site) or dropped on the page. The archive is unpacked into the page's file system under
// /courses/NAME (NAME: the zip's name without .zip) and handed to the app, which lists its exercises
// before the built-in ones (app/ui/exercise_panel.cpp), as the desktop's --exercises DIR does.
//
// A course zip is untrusted input: its names are checked before anything is written (no absolute
// paths, no "..", nothing outside the course's folder), it is read within limits (entries, bytes,
// each entry's declared size), and whatever is wrong comes back as one line naming the zip.
'use strict';

const ShadeLabCourse = (() => {
  const kMaxEntries = 4096;
  const kMaxBytes = 64 << 20;  // all files together, unpacked
  const kSafePart = /^[A-Za-z0-9_][A-Za-z0-9_.\- ]*$/;

  // An entry's bytes inflated (zip's method 8), stopped as soon as they pass what its header declared.
  async function inflate(compressed, size, name) {
    const reader = new Blob([compressed]).stream().pipeThrough(new DecompressionStream('deflate-raw')).getReader();
    const out = new Uint8Array(size);
    let filled = 0;
    for (;;) {
      const { done, value } = await reader.read();
      if (done) break;
      if (filled + value.length > size) {
        reader.cancel();
        throw `${name} unpacks to more than the ${size} bytes its header declares`;
      }
      out.set(value, filled);
      filled += value.length;
    }
    if (filled !== size) throw `${name} unpacks to ${filled} bytes, not the ${size} its header declares`;
    return out;
  }

  // The archive's files as [{ path, bytes }] (folders left out), read through its central directory.
  async function unzip(buffer, zipName) {
    const view = new DataView(buffer);
    const length = buffer.byteLength;
    const fail = (what) => { throw `${zipName}: ${what}`; };
    let end = -1;  // the end-of-central-directory record: in the last 22 + 65535 bytes (its comment)
    for (let at = length - 22; at >= Math.max(0, length - 22 - 65535); --at)
      if (view.getUint32(at, true) === 0x06054b50) { end = at; break; }
    if (end < 0) fail('not a zip archive (it has no central directory)');
    const count = view.getUint16(end + 10, true);
    if (count === 0xffff || view.getUint32(end + 16, true) === 0xffffffff) fail('a ZIP64 archive (not read; a course is small)');
    if (count > kMaxEntries) fail(`${count} entries (at most ${kMaxEntries})`);
    const files = [];
    let at = view.getUint32(end + 16, true), total = 0;
    for (let n = 0; n < count; ++n) {
      if (at + 46 > length || view.getUint32(at, true) !== 0x02014b50) fail(`its central directory is damaged at entry ${n + 1}`);
      const flags = view.getUint16(at + 8, true), method = view.getUint16(at + 10, true);
      const compressedSize = view.getUint32(at + 20, true), size = view.getUint32(at + 24, true);
      const nameLength = view.getUint16(at + 28, true);
      const local = view.getUint32(at + 42, true);
      if (at + 46 + nameLength > length) fail(`its central directory is damaged at entry ${n + 1}`);
      const path = new TextDecoder().decode(new Uint8Array(buffer, at + 46, nameLength));
      at += 46 + nameLength + view.getUint16(at + 30, true) + view.getUint16(at + 32, true);
      if (path.endsWith('/')) continue;
      if (flags & 1) fail(`${path} is encrypted`);
      if ((total += size) > kMaxBytes) fail(`its files unpack to more than ${kMaxBytes >> 20} MiB`);
      if (local + 30 > length || view.getUint32(local, true) !== 0x04034b50) fail(`${path}'s local header is damaged`);
      const start = local + 30 + view.getUint16(local + 26, true) + view.getUint16(local + 28, true);
      if (start + compressedSize > length) fail(`${path} runs past the end of the archive`);
      const stored = new Uint8Array(buffer, start, compressedSize);
      let bytes;
      if (method === 0 && compressedSize === size) bytes = stored.slice();
      else if (method === 8) bytes = await inflate(stored, size, `${zipName}: ${path}`);
      else fail(`${path} is packed with method ${method} (valid: 0, stored; 8, deflate)`);
      files.push({ path, bytes });
    }
    return files;
  }

  // The course's folder inside the archive: where every LAB/NAME/rubric.json hangs from ("" for the
  // archive's top, "week3/" for a zip of the folder week3). Archive clutter (__MACOSX/, dot files) is skipped.
  function courseRoot(files, zipName) {
    const rubrics = files.map((f) => f.path.split('/'))
      .filter((parts) => parts[parts.length - 1] === 'rubric.json' && parts.length >= 3 &&
                         !parts.some((p) => p.startsWith('.') || p === '__MACOSX'));
    if (rubrics.length === 0) throw `${zipName} holds no exercise (a course holds LAB/NAME/rubric.json; exercises/README.md)`;
    const roots = new Set(rubrics.map((parts) => parts.slice(0, -3).map((p) => p + '/').join('')));
    if (roots.size > 1) throw `${zipName} holds exercises at different depths (${[...roots].map((r) => r || '(top)').join(', ')}): zip one course folder`;
    return [...roots][0];
  }

  // What went wrong, naming the zip: the lines thrown here name it already; a file-system or network
  // error does not.
  function named(zipName, problem) {
    return typeof problem === 'string' ? problem : `${zipName}: ${problem && problem.message ? problem.message : problem}`;
  }

  function removeTree(FS, path) {
    if (!FS.analyzePath(path).exists) return;
    for (const name of FS.readdir(path)) {
      if (name === '.' || name === '..') continue;
      const child = path + '/' + name;
      if (FS.isDir(FS.stat(child).mode)) removeTree(FS, child); else FS.unlink(child);
    }
    FS.rmdir(path);
  }

  // Unpacks the zip's bytes into /courses/NAME and returns that folder; an older copy of the same
  // course is replaced (a teacher's corrected zip, dropped again).
  async function unpack(FS, buffer, zipName) {
    const name = zipName.replace(/^.*\//, '').replace(/\.zip$/i, '');
    if (!kSafePart.test(name)) throw `${zipName}: a course's name is letters, digits, '_', '-', '.' and spaces`;
    const files = await unzip(buffer, zipName);
    for (const f of files)
      if (f.path.startsWith('/') || f.path.includes('\\') || f.path.split('/').some((p) => p === '..' || p === ''))
        throw `${zipName}: '${f.path}' leaves the course's folder (a zip's names are relative, without '..')`;
    const root = courseRoot(files, zipName);
    const folder = '/courses/' + name;
    const kept = [];
    for (const f of files) {
      if (!f.path.startsWith(root)) continue;
      const parts = f.path.slice(root.length).split('/');
      if (parts.some((p) => p.startsWith('.') || p === '__MACOSX')) continue;
      if (!parts.every((p) => kSafePart.test(p))) throw `${zipName}: '${f.path}' is not a course file's name (letters, digits, '_', '-', '.')`;
      kept.push({ parts, bytes: f.bytes });
    }
    removeTree(FS, folder);
    for (const f of kept) {
      FS.mkdirTree([folder, ...f.parts.slice(0, -1)].join('/'));
      FS.writeFile([folder, ...f.parts].join('/'), f.bytes);
    }
    return folder;
  }

  // The link's course=NAME.zip (as the link has it, percent-encoded): a zip beside the page on the
  // same site, fetched and unpacked before the app starts. Resolves to { folder } or { problem } (the
  // app shows it in its Messages panel); never rejects, so the page never waits on it for ever.
  async function openFromLink(FS, encoded) {
    let value = encoded, url = null;
    try {
      value = decodeURIComponent(encoded);
      url = new URL(value, location.href);
    } catch (e) {
      // a malformed escape or address: refused below
    }
    if (!url || url.origin !== location.origin || !/\.zip$/i.test(url.pathname))
      return { problem: `the link's course=${value}: a .zip file of this site (valid: course=week3.zip)` };
    try {
      const response = await fetch(url);
      if (!response.ok) return { problem: `the link's course=${value}: the site answered ${response.status} ${response.statusText}` };
      return { folder: await unpack(FS, await response.arrayBuffer(), value) };
    } catch (e) {
      return { problem: named(value, e) };
    }
  }

  // Zips dropped on the page are taken here, before the app's own drop (meshes, shaders, presets):
  // each is unpacked and handed to the app with opened(folder, problem).
  function takeDroppedZips(FS, opened) {
    window.addEventListener('drop', (event) => {
      const zips = [...(event.dataTransfer ? event.dataTransfer.files : [])].filter((f) => /\.zip$/i.test(f.name));
      if (zips.length === 0) return;
      event.preventDefault();
      event.stopPropagation();  // the app's drop would write the zip into its file system as a mesh
      for (const file of zips)
        file.arrayBuffer().then((buffer) => unpack(FS, buffer, file.name))
          .then((folder) => opened(folder, ''), (problem) => opened('', named(file.name, problem)));
    }, true);
  }

  return { openFromLink, takeDroppedZips, unpack };
})();
