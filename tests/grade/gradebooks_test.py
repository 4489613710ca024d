#!/usr/bin/env python3
"""Every gradebook format on three submissions of shading/blinn-phong: one that passes (the lab's own
file), one that fails (the starter), one that cannot be graded (a syntax error; for PrairieLearn also
a missing file). Each platform's script runs as the platform runs it, on a fake tree (no network):
Gradescope's run_autograder on /autograder, Classroom 50's autograder.py in a git checkout with the
runner's environment, PrairieLearn's run.sh on /grade. Each JSON file is validated against the
schema of tests/grade/schemas/ (written from what the platform publishes) with jsonschema, plus the
rules a schema cannot say; Moodle's and Canvas's CSV come from one `grade --class` of the three.

usage: gradebooks_test.py SHADELAB_BINARY REPO OUT_DIR     prints "passed: ..." at the end
"""
import csv
import json
import os
import pathlib
import shutil
import subprocess
import sys

import jsonschema

shadelab, repo, out = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3])
EXERCISE = 'shading/blinn-phong'
FILE = 'common/specular.glsl'
schemas = repo / 'tests/grade/schemas'


def schema(name):
    return jsonschema.Draft202012Validator(json.loads((schemas / name).read_text()))


def submissions():
    """name -> the text of common/specular.glsl (None: the file is missing)."""
    solution = (repo / 'shaders' / FILE).read_text()
    return {'passing': solution,
            'failing': (repo / 'exercises' / EXERCISE / 'starter' / FILE).read_text(),
            'broken': solution.replace('{', '{ this is not GLSL', 1)}


def run(command, **kw):
    done = subprocess.run([str(c) for c in command], capture_output=True, text=True, **kw)
    if done.returncode != 0:
        sys.exit(f'{command[0]} exited {done.returncode}:\n{done.stdout}\n{done.stderr}')
    return done


def gradescope(name, text):
    tree = out / 'gradescope' / name
    (tree / 'source').mkdir(parents=True)
    (tree / 'source/config.env').write_text(f'EXERCISE={EXERCISE}\n')
    (tree / 'submission' / FILE).parent.mkdir(parents=True)
    (tree / 'submission' / FILE).write_text(text)
    run([repo / 'tools/gradescope/run_autograder'], env=dict(os.environ, AUTOGRADER=str(tree), SHADELAB=str(shadelab)))
    r = json.loads((tree / 'results/results.json').read_text())
    schema('gradescope-results.schema.json').validate(r)
    assert abs(sum(t['score'] for t in r['tests']) - r['score']) < 1e-9, 'the tests add up to the score'
    assert all(t['score'] <= t['max_score'] for t in r['tests'])
    assert r['output_format'] == 'md'
    passed = all(t['status'] == 'passed' for t in r['tests'])
    assert passed == (name == 'passing'), (name, [t['status'] for t in r['tests']])
    if name == 'broken':
        assert 'did not build' in r['output'], r['output']
    return r['score']


def classroom50(name, text):
    checkout = out / 'classroom50' / name
    (checkout / 'shaders' / FILE).parent.mkdir(parents=True)
    (checkout / 'shaders' / FILE).write_text(text)
    git = ['git', '-C', checkout, '-c', 'user.name=student', '-c', 'user.email=student@example.org']
    run(git[:3] + ['init', '-q'])
    run(git + ['add', '.'])
    run(git + ['commit', '-q', '-m', 'my answer'], env=dict(os.environ, GIT_COMMITTER_DATE='2026-11-27T23:59:58+01:00'))
    grader = out / 'classroom50' / 'autograders' / 'blinn-phong'
    if not grader.is_dir():
        grader.mkdir(parents=True)
        shutil.copy(repo / 'tools/classroom50/autograder.py', grader)
        (grader / 'autograder.json').write_text(json.dumps({'exercise': EXERCISE, 'shaders': 'shaders'}))
    env = dict(os.environ, SHADELAB=str(shadelab), CLASSROOM='graphics', ASSIGNMENT='blinn-phong',
               ASSIGNMENT_TYPE='individual', OWNER=name, SUBMISSION_TAG='submit/2026-11-27T22-59-58Z-abc1234',
               COMMIT_URL='https://example.org/commit/abc1234', RELEASE_URL='https://example.org/releases/1',
               REVIEW_URL='https://example.org/compare/0...abc1234', GITHUB_ACTOR=name)
    env.pop('COMMIT_DATE', None)
    run([sys.executable, grader / 'autograder.py'], cwd=checkout, env=env)
    r = json.loads((checkout / 'result.json').read_text())
    schema('classroom50-result-v1.schema.json').validate(r)
    assert r['datetime'] == '2026-11-27T22:59:58Z', 'the commit date, in UTC: ' + r['datetime']
    assert r['score'] == sum(t['score'] for t in r['tests']) <= r['max-score'] == sum(t['max-score'] for t in r['tests'])
    assert all(t['score'] <= t['max-score'] for t in r['tests'])
    assert (r['score'] == r['max-score']) == (name == 'passing'), (name, r['score'], r['max-score'])
    for asset in ('release-body.md', 'shadelab-report.html', 'shadelab-pictures.zip'):
        assert (checkout / asset).is_file(), asset + ' for the release'
    return r['score'] / r['max-score']


def prairielearn(name, text):
    grade = out / 'prairielearn' / name
    (grade / 'student').mkdir(parents=True)
    if text is not None:
        (grade / 'student' / pathlib.Path(FILE).name).write_text(text)  # an upload is flat
    run([repo / 'tools/prairielearn/run.sh'], env=dict(os.environ, GRADE_ROOT=str(grade), SHADELAB=str(shadelab),
                                                       EXERCISE=EXERCISE))
    path = grade / 'results/results.json'
    r = json.loads(path.read_text())
    schema('prairielearn-results.schema.json').validate(r)
    assert path.stat().st_size <= 1000000, f'{path.stat().st_size} bytes: over PrairieLearn\'s 1 MB'
    if name in ('broken', 'missing'):
        assert r['gradable'] is False, name + ' is not gradable: no attempt charged'
        errors = ' '.join(r['format_errors'])
        assert ('error' in errors) if name == 'broken' else (FILE in errors), errors
        return None
    assert r['gradable'] is True
    failing = [t for t in r['tests'] if t['points'] < t['max_points']]
    assert bool(failing) == (name == 'failing')
    with_pictures = [t for t in failing if t.get('images')]
    assert not failing or len(with_pictures[0]['images']) == 3, 'the frame, the solution\'s, the difference'
    return r['score']


def class_csvs(subs):
    klass = out / 'class'
    for name, text in subs.items():
        (klass / name / FILE).parent.mkdir(parents=True)
        (klass / name / FILE).write_text(text)
    for fmt in ('moodle', 'canvas'):
        run([shadelab, 'grade', '--class', klass, '--exercise', EXERCISE, '--format', fmt, '--out',
             out / f'class-{fmt}'])
    moodle = list(csv.reader(open(out / 'class-moodle/moodle.csv', newline='')))
    assert moodle[0][0] == 'Username' and len(moodle) == 1 + len(subs)
    assert moodle[0][2] == 'Feedback: ' + moodle[0][1], 'the feedback column right beside its grade column'
    assert all(len(row) == len(moodle[0]) for row in moodle)
    assert all(row[1] != '' for row in moodle[1:]), 'every graded row has its grade beside its feedback'
    canvas = list(csv.reader(open(out / 'class-canvas/canvas.csv', newline='')))
    assert canvas[0][:5] == ['Student', 'ID', 'SIS User ID', 'SIS Login ID', 'Section']
    assert canvas[1][0].strip() == 'Points Possible' and len(canvas) == 2 + len(subs)


def hidden_configuration():
    """A rubric's configuration hidden until the due date (the test course's point-lights, "per
    vertex"): graded and counted, its tests carrying that visibility in Gradescope's results."""
    course = repo / 'tests/data/course'
    student = out / 'hidden' / 'student'
    shutil.copytree(course / 'shading/point-lights/starter', student)
    done = subprocess.run([str(c) for c in [shadelab, 'grade', '--exercises', course, '--exercise',
                                            'shading/point-lights', '--shaders', student, '--format', 'gradescope',
                                            '--out', out / 'hidden/report']], capture_output=True, text=True)
    assert done.returncode in (0, 1), done.stdout + done.stderr
    r = json.loads((out / 'hidden/report/results.json').read_text())
    schema('gradescope-results.schema.json').validate(r)
    hidden = [t for t in r['tests'] if ': per vertex: ' in t['name']]
    assert hidden and all(t['visibility'] == 'after_due_date' for t in hidden), hidden
    assert all(t['visibility'] == 'visible' for t in r['tests'] if t not in hidden)
    assert abs(sum(t['score'] for t in r['tests']) - r['score']) < 1e-9, 'the hidden tests are counted'


def main():
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    subs = submissions()
    seen = {}
    for name, text in subs.items():
        seen[name] = (gradescope(name, text), classroom50(name, text), prairielearn(name, text))
    assert prairielearn('missing', None) is None
    class_csvs(subs)
    hidden_configuration()
    assert seen['passing'][2] == 1.0 and seen['failing'][2] < 0.7, seen
    print('passed: gradescope, classroom50, prairielearn and moodle/canvas on a passing, a failing and an '
          'ungradable submission, and a hidden configuration graded:', json.dumps(seen))


if __name__ == '__main__':
    main()
