// The exercise in the page as text: its statement (Markdown) and the last Check's lines, in the
// document beside the canvas, where they can be selected, copied, read aloud and translated. The
// app calls ShadeLabExercise.show whenever they change (platform_web.cpp). Text is only ever set
// as text: a statement or a line is never parsed as HTML.
const ShadeLabExercise = (() => {
  const el = (tag, className, text) => {
    const e = document.createElement(tag);
    if (className) e.className = className;
    if (text !== undefined) e.textContent = text;
    return e;
  };
  // `code` spans and **bold** inside a line of prose; the rest as it is (formulas stay text).
  function inline(parent, text) {
    text = text.replace(/\[([^\]]+)\]\([^)]*\)/g, '$1');  // a link's text: its target lies outside the page
    for (const part of text.split(/(`[^`]*`|\*\*[^*]+\*\*)/)) {
      if (part.startsWith('`') && part.endsWith('`') && part.length > 1) parent.appendChild(el('code', '', part.slice(1, -1)));
      else if (part.startsWith('**') && part.endsWith('**') && part.length > 3) parent.appendChild(el('strong', '', part.slice(2, -2)));
      else if (part) parent.appendChild(document.createTextNode(part));
    }
  }
  // Headings, fenced code, lists, paragraphs: what exercise statements use.
  function markdown(text) {
    const out = document.createDocumentFragment();
    const lines = text.replace(/\r/g, '').split('\n');
    let paragraph = [], list = null;
    const flush = () => {
      if (paragraph.length) { const p = el('p'); inline(p, paragraph.join(' ')); out.appendChild(p); }
      paragraph = [];
      list = null;
    };
    for (let i = 0; i < lines.length; ++i) {
      const line = lines[i];
      if (/^\s*```/.test(line)) {
        flush();
        const code = [];
        while (++i < lines.length && !/^\s*```/.test(lines[i])) code.push(lines[i]);
        out.appendChild(el('pre', '', code.join('\n')));
      } else if (!paragraph.length && !list && (/^( {4}|\t)/.test(line) || /^\s*\|/.test(line))) {
        // An indented block (formulas laid out in columns) or a table: kept as it is, in monospace.
        flush();
        const table = /^\s*\|/.test(line), block = [line.replace(/^( {4}|\t)/, '')];
        while (i + 1 < lines.length && (table ? /^\s*\|/.test(lines[i + 1]) : /^( {4}|\t)/.test(lines[i + 1])))
          block.push(lines[++i].replace(table ? /^/ : /^( {4}|\t)/, ''));
        out.appendChild(el('pre', '', block.join('\n')));
      } else if (/^#{1,6}\s/.test(line)) {
        flush();
        const level = Math.min(line.match(/^#+/)[0].length + 1, 6);  // the page's own title is h1
        const h = el('h' + level);
        inline(h, line.replace(/^#+\s*/, ''));
        out.appendChild(h);
      } else if (/^\s*([-*]|\d+\.)\s/.test(line)) {
        const ordered = /^\s*\d+\./.test(line);
        if (paragraph.length) { const keep = list; flush(); list = keep; }
        if (!list || (list.tagName === 'OL') !== ordered) { list = el(ordered ? 'ol' : 'ul'); out.appendChild(list); }
        const li = el('li');
        inline(li, line.replace(/^\s*([-*]|\d+\.)\s+/, ''));
        list.appendChild(li);
      } else if (!line.trim()) {
        flush();
      } else if (list && /^\s+/.test(line)) {  // a list item's continued line
        inline(list.lastChild, ' ' + line.trim());
      } else {
        list = null;
        paragraph.push(line.trim());
      }
    }
    flush();
    return out;
  }
  function show(id, statement, lines) {
    const aside = document.getElementById('exercise');
    aside.hidden = !id;
    const title = document.getElementById('exercise-title');
    title.textContent = id ? 'Exercise ' + id : '';
    const body = document.getElementById('exercise-statement');
    body.replaceChildren(markdown(statement));
    const check = document.getElementById('exercise-check');
    check.replaceChildren();
    for (const line of lines.split('\n').filter((l) => l.length)) {
      const kind = /^\s*(PASS|PARTIAL|FAIL)\b/.exec(line);
      const d = el('div', kind ? kind[1].toLowerCase() : /^diagnosis:|^\S.*points \(/.test(line) ? 'summary' : '', line);
      check.appendChild(d);
    }
    document.getElementById('exercise-check-title').hidden = !lines;
    window.dispatchEvent(new Event('resize'));  // the canvas takes the width the text leaves
  }
  return { show, markdown };
})();
