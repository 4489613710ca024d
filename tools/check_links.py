#!/usr/bin/env python3
"""Every relative link of the project's pages points at a file that exists, and every #anchor at a
heading of that page (GitHub's heading ids). Outside links (http, https, mailto) are not fetched.

usage: tools/check_links.py [ROOT]     prints one line per broken link and exits 1, else "links: N ok"
"""
import pathlib
import re
import sys

LINK = re.compile(r'!?\[[^\]]*\]\(([^)\s]+)(?:\s+"[^"]*")?\)')
FENCE = re.compile(r'^\s*(```|~~~)')


def pages(root):
    yield root / 'README.md'
    for folder in ('docs', 'tutorials'):
        yield from sorted((root / folder).glob('*.md'))
    for name in ('exercises/README.md', 'labs/README.md'):
        if (root / name).exists():
            yield root / name


def prose_lines(path):
    """(line number, text) outside fenced code blocks."""
    fenced = False
    for number, line in enumerate(path.read_text(encoding='utf-8').splitlines(), 1):
        if FENCE.match(line):
            fenced = not fenced
            continue
        if not fenced:
            yield number, line


def heading_ids(path):
    """GitHub's ids: lower case, markup and punctuation dropped, spaces to hyphens, repeats -1, -2."""
    ids, seen = set(), {}
    for _, line in prose_lines(path):
        m = re.match(r'^#{1,6}\s+(.*?)\s*#*\s*$', line)
        if not m:
            continue
        text = re.sub(r'\[([^\]]*)\]\([^)]*\)', r'\1', m.group(1)).lower()
        slug = re.sub(r'[^\w\- ]', '', text).replace(' ', '-')
        n = seen.get(slug, 0)
        seen[slug] = n + 1
        ids.add(slug if n == 0 else f'{slug}-{n}')
    return ids


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent.parent).resolve()
    broken, count = [], 0
    for page in pages(root):
        for number, line in prose_lines(page):
            for target in LINK.findall(line):
                if re.match(r'^(https?|mailto):', target):
                    continue
                count += 1
                file, _, anchor = target.partition('#')
                dest = (page.parent / file).resolve() if file else page
                where = f'{page.relative_to(root)}:{number}: {target}'
                if not dest.exists():
                    broken.append(f'{where}: no such file')
                elif root not in dest.parents and dest != root:
                    broken.append(f'{where}: outside the repository')
                elif anchor and dest.suffix == '.md' and anchor not in heading_ids(dest):
                    broken.append(f'{where}: no heading with the id "{anchor}"')
    for line in broken:
        print(line)
    if broken:
        return 1
    print(f'links: {count} ok')
    return 0


if __name__ == '__main__':
    sys.exit(main())
