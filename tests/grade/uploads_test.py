#!/usr/bin/env python3
"""Uploads as students make them, through each platform's own entry point: a flat specular.glsl, a
folder, a zip of a folder with and without its top folder (Gradescope's run_autograder on a fake
/autograder, PrairieLearn's run.sh on a fake /grade, Classroom 50's autograder.py in a git
checkout with the runner's environment), each scoring what `shadelab grade --shaders` gives the
same file laid out as shaders/. Then the uploads that need a word: a name in another case, two
files that could be the one asked for (which was taken, and why), an extra file (ignored, listed)
and a missing one (named, with where it was looked for).

usage: uploads_test.py SHADELAB_BINARY REPO OUT_DIR     prints "passed: ..." at the end
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import zipfile

shadelab, repo, out = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3]).resolve()
EXERCISE = 'shading/blinn-phong'
FILE = 'common/specular.glsl'
# A submission that earns some of the points, not all: the half vector left unnormalised.
SOLUTION = (repo / 'shaders' / FILE).read_text()
TEXT = SOLUTION.replace('safeNormalize(L + V, N)', '(L + V)')
assert TEXT != SOLUTION
STARTER = (repo / 'exercises' / EXERCISE / 'starter' / FILE).read_text()


def run(command, **kw):
    done = subprocess.run([str(c) for c in command], capture_output=True, text=True, **kw)
    if done.returncode != 0:
        sys.exit(f'{command[0]} exited {done.returncode}:\n{done.stdout}\n{done.stderr}')
    return done


def write(path, text):
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)


def zipped(path, entries):
    path.parent.mkdir(parents=True, exist_ok=True)
    with zipfile.ZipFile(path, 'w') as z:
        for name, text in entries.items():
            z.writestr(name, text)


# Each layout fills an upload folder as the student's hand-in arrives there.
LAYOUTS = {
    'flat': lambda d: write(d / 'specular.glsl', TEXT),
    'folder': lambda d: write(d / 'my_shaders' / FILE, TEXT),
    'zip with its top folder': lambda d: zipped(d / 'my_shaders.zip', {'my_shaders/' + FILE: TEXT}),
    'zip without a top folder': lambda d: zipped(d / 'shaders.zip', {FILE: TEXT, '__MACOSX/._specular.glsl': 'x'}),
    'another case': lambda d: write(d / 'Specular.GLSL', TEXT),
    'duplicate': lambda d: (write(d / 'my_shaders' / FILE, TEXT), write(d / 'old' / 'specular.glsl', STARTER)),
    'extra file': lambda d: (write(d / 'specular.glsl', TEXT), write(d / 'README.txt', 'my notes')),
    'missing': lambda d: write(d / 'notes.txt', 'I ran out of time'),
}
# What the notes must say for the layouts that need a word.
NOTES = {
    'another case': ['Specular.GLSL taken by its name in another case'],
    'duplicate': ['2 files could be common/specular.glsl: took my_shaders/common/specular.glsl (found at its path), '
                  'not old/specular.glsl'],
    'extra file': ['ignored, not among the exercise\'s files: README.txt', 'specular.glsl taken by its name'],
    'missing': ['not in the upload: common/specular.glsl (looked for at that path, then by name in any case, in '
                'every folder of'],
}


def reference():
    """What `shadelab grade` gives the file laid out as shaders/: (points, total)."""
    shaders = out / 'reference' / 'shaders'
    write(shaders / FILE, TEXT)
    done = subprocess.run([str(shadelab), 'grade', '--exercise', EXERCISE, '--shaders', str(shaders), '--out',
                           str(out / 'reference' / 'report'), '--no-cache'], capture_output=True, text=True)
    assert done.returncode in (0, 1), done.stdout + done.stderr
    e = json.loads((out / 'reference' / 'report' / 'report.json').read_text())['exercises'][0]
    assert 0 < e['score'] < e['total'], ('the reference earns some points, not all', e['score'], e['total'])
    return e['score'], e['total']


def gradescope(layout):
    tree = out / 'gradescope' / layout.replace(' ', '-')
    write(tree / 'source/config.env', f'EXERCISE={EXERCISE}\n')
    (tree / 'submission').mkdir(parents=True)
    LAYOUTS[layout](tree / 'submission')
    run([repo / 'tools/gradescope/run_autograder'], env=dict(os.environ, AUTOGRADER=str(tree), SHADELAB=str(shadelab)))
    r = json.loads((tree / 'results/results.json').read_text())
    return r['score'], r['output']


def prairielearn(layout):
    grade = out / 'prairielearn' / layout.replace(' ', '-')
    (grade / 'student').mkdir(parents=True)
    LAYOUTS[layout](grade / 'student')
    run([repo / 'tools/prairielearn/run.sh'], env=dict(os.environ, GRADE_ROOT=str(grade), SHADELAB=str(shadelab),
                                                       EXERCISE=EXERCISE))
    r = json.loads((grade / 'results/results.json').read_text())
    return r.get('score'), r['output'], r


def classroom50(layout):
    checkout = out / 'classroom50' / layout.replace(' ', '-')
    (checkout / 'shaders').mkdir(parents=True)
    LAYOUTS[layout](checkout / 'shaders')
    git = ['git', '-C', checkout, '-c', 'user.name=student', '-c', 'user.email=student@example.org']
    run(git[:3] + ['init', '-q'])
    run(git + ['add', '.'])
    run(git + ['commit', '-q', '-m', 'my answer'])
    grader = out / 'classroom50' / 'autograders' / 'blinn-phong'
    if not grader.is_dir():
        grader.mkdir(parents=True)
        shutil.copy(repo / 'tools/classroom50/autograder.py', grader)
        (grader / 'autograder.json').write_text(json.dumps({'exercise': EXERCISE, 'shaders': 'shaders'}))
    env = dict(os.environ, SHADELAB=str(shadelab), CLASSROOM='graphics', ASSIGNMENT='blinn-phong',
               ASSIGNMENT_TYPE='individual', OWNER='student', SUBMISSION_TAG='submit/2026-11-27T22-59-58Z-abc1234',
               COMMIT_URL='https://example.org/commit/abc1234', RELEASE_URL='https://example.org/releases/1',
               REVIEW_URL='https://example.org/compare/0...abc1234', GITHUB_ACTOR='student')
    run([sys.executable, grader / 'autograder.py'], cwd=checkout, env=env)
    r = json.loads((checkout / 'result.json').read_text())
    return r['score'], r['max-score'], (checkout / 'release-body.md').read_text()


def main():
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    points, total = reference()
    seen = {}
    for layout in ('flat', 'folder', 'zip with its top folder', 'zip without a top folder'):
        g, _ = gradescope(layout)
        p, _, _ = prairielearn(layout)
        c, most, _ = classroom50(layout)
        assert abs(g - points) < 1e-9, (layout, 'gradescope', g, points)
        assert abs(p - points / total) < 1e-9, (layout, 'prairielearn', p, points / total)
        assert abs(c / most - points / total) < 1e-9, (layout, 'classroom50', c, most, points, total)
        seen[layout] = g
    for layout, notes in NOTES.items():
        g, output = gradescope(layout)
        p, pl_output, r = prairielearn(layout)
        for note in notes:
            assert note in output, (layout, 'gradescope', note, output)
            assert note in pl_output, (layout, 'prairielearn', note, pl_output)
        if layout == 'missing':
            assert g == 0, g
            assert r['gradable'] is False and FILE + ' is not in the submission' in r['format_errors'], r
        else:
            assert abs(g - points) < 1e-9 and abs(p - points / total) < 1e-9, (layout, g, p, points)
        seen[layout] = g
    print(f'passed: every upload scored what shadelab grade gives the same file ({points:g} of {total:g}) through '
          f'each platform\'s entry point:', json.dumps(seen))


if __name__ == '__main__':
    main()
