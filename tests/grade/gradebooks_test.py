#!/usr/bin/env python3
"""Every gradebook format on three submissions of shading/blinn-phong: one that passes (the lab's own
file), one that fails (the starter), one that cannot be graded (a syntax error; for PrairieLearn also
a missing file). Each platform's script runs as the platform runs it, on a fake tree (no network):
Gradescope's run_autograder on /autograder, Classroom 50's autograder.py in a git checkout with the
runner's environment, PrairieLearn's run.sh on /grade. Each JSON file is validated against the
schema of tests/grade/schemas/ (written from what the platform publishes) with jsonschema, plus the
rules a schema cannot say; Moodle's and Canvas's CSV come from one `grade --class` of the three, and
again from the three laid out as each platform's own download of an assignment. Each platform's
entry point also grades with the solutions its image prepares when it is built (`grade --prepare`),
rendering none of them.

usage: gradebooks_test.py SHADELAB_BINARY REPO OUT_DIR     prints "passed: ..." at the end
"""
import csv
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys

import jsonschema

shadelab, repo, out = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]), pathlib.Path(sys.argv[3]).resolve()
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


def classroom50_env(name):
    """The environment Classroom 50's runner hands the autograder for `name`'s submission, and its release."""
    tag = 'submit/2026-11-27T22-59-58Z-abc1234'
    release = f'https://github.com/graphics/blinn-phong-{name}/releases/tag/{tag}'
    env = dict(os.environ, SHADELAB=str(shadelab), CLASSROOM='graphics', ASSIGNMENT='blinn-phong',
               ASSIGNMENT_TYPE='team' if name == 'failing' else 'individual', OWNER=name, SUBMISSION_TAG=tag,
               COMMIT_URL='https://example.org/commit/abc1234', RELEASE_URL=release,
               REVIEW_URL='https://example.org/compare/0...abc1234', GITHUB_ACTOR=name)
    env.pop('COMMIT_DATE', None)
    return env, release


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
    env, release = classroom50_env(name)
    run([sys.executable, grader / 'autograder.py'], cwd=checkout, env=env)
    r = json.loads((checkout / 'result.json').read_text())
    schema('classroom50-result-v1.schema.json').validate(r)
    assert r['datetime'] == '2026-11-27T22:59:58Z', 'the commit date, in UTC: ' + r['datetime']
    assert r['score'] == sum(t['score'] for t in r['tests']) <= r['max-score'] == sum(t['max-score'] for t in r['tests'])
    assert all(t['score'] <= t['max-score'] for t in r['tests'])
    assert (r['score'] == r['max-score']) == (name == 'passing'), (name, r['score'], r['max-score'])
    assert r['assignment_type'] == ('group' if name == 'failing' else 'individual'), r['assignment_type']
    for asset in ('release-body.md', 'shadelab-report.html', 'shadelab-pictures.zip'):
        assert (checkout / asset).is_file(), asset + ' for the release'
    # Every picture and link of the release's text names an asset the release carries: a file the
    # autograder left, listed in the assignment's release_assets (autograder.py --release-assets).
    listed = json.loads(run([sys.executable, grader / 'autograder.py', '--release-assets'], env=env).stdout)
    body = (checkout / 'release-body.md').read_text()
    download = release.replace('/releases/tag/', '/releases/download/') + '/'
    references = re.findall(r'!?\[[^\]]*\]\(([^)\s]+)\)', body)
    assert references, 'the body links the report and the pictures'
    for url in references:
        assert url.startswith(download), url + ': not an asset of ' + release
        asset = url[len(download):]
        assert (checkout / asset).is_file() and asset in listed, asset + ': not attached to the release'
    pictures = re.findall(r'!\[[^\]]*\]\(([^)\s]+)\)', body)
    assert bool(pictures) == (name != 'passing'), (name, pictures)
    return r['score'] / r['max-score'], r['max-score']


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
    assert path.stat().st_size <= 1048576, f'{path.stat().st_size} bytes: over PrairieLearn\'s 1,048,576'
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


def platform_downloads(subs):
    """Moodle's "Download all submissions" (a folder per participant, and loose files) and Canvas's
    "Download Submissions" (loose files, a late one, a re-uploaded name, a zip), graded with --class as
    they come: each gradebook row names the identity the platform matches (Moodle's participant,
    Canvas's user id) and scores what the same file scores in a folder named by the student."""
    named = {row[0]: row[1] for row in csv.reader(open(out / 'class-moodle/moodle.csv', newline=''))}
    moodle = out / 'moodle-download'
    (moodle / 'Ada Lovelace_101_assignsubmission_file_').mkdir(parents=True)
    (moodle / 'Ada Lovelace_101_assignsubmission_file_/specular.glsl').write_text(subs['passing'])
    (moodle / 'Grace Hopper_102_assignsubmission_file_/shaders/common').mkdir(parents=True)
    (moodle / 'Grace Hopper_102_assignsubmission_file_/shaders/common/specular.glsl').write_text(subs['failing'])
    (moodle / 'Grace Hopper_102_assignsubmission_onlinetext_').mkdir()
    (moodle / 'Grace Hopper_102_assignsubmission_onlinetext_/onlinetext.html').write_text('<p>done</p>')
    (moodle / 'Alan Turing_103_assignsubmission_file_specular.glsl').write_text(subs['broken'])
    done = run([shadelab, 'grade', '--class', moodle, '--exercise', EXERCISE, '--format', 'moodle', '--out',
                out / 'moodle-graded'])
    assert "read as Moodle's" in done.stdout, done.stdout
    sheet = list(csv.reader(open(out / 'moodle-graded/moodle-worksheet.csv', newline='')))
    assert sheet[0][:3] == ['Identifier', 'Full name', 'Grade'] and 'Last modified (grade)' in sheet[0], sheet[0]
    grades = {row[0]: row[2] for row in sheet[1:]}
    assert grades == {'Participant 101': named['passing'], 'Participant 102': named['failing'],
                      'Participant 103': named['broken']}, (grades, named)

    canvas = out / 'canvas-download'
    canvas.mkdir()
    (canvas / 'lovelaceada_201_9001_specular.glsl').write_text(subs['passing'])
    (canvas / 'hoppergrace_late_202_9002_specular-1.glsl').write_text(subs['failing'])
    import zipfile
    with zipfile.ZipFile(canvas / 'turingalan_203_9003_my_shaders.zip', 'w') as z:
        z.writestr('my_shaders/common/specular.glsl', subs['broken'])
    done = run([shadelab, 'grade', '--class', canvas, '--exercise', EXERCISE, '--format', 'canvas', '--out',
                out / 'canvas-graded'])
    assert "read as Canvas's" in done.stdout, done.stdout
    table = list(csv.reader(open(out / 'canvas-graded/canvas.csv', newline='')))
    scores = {row[1]: row[5] for row in table[2:]}
    assert scores == {'201': named['passing'], '202': named['failing'], '203': named['broken']}, (scores, named)
    report = (out / 'canvas-graded/students/hoppergrace_202/report.md').read_text()
    assert 'specular-1.glsl read as specular.glsl' in report, report[:2000]


def prepared_solutions(subs, seen):
    """An autograder's image draws the exercise's solution side once, when it is built (`grade
    --prepare`: Gradescope's setup.sh, the PrairieLearn and Classroom 50 Dockerfiles). A submission
    graded there takes every configuration's solution from that cache, renders none, and scores what
    it scores with the solution drawn for it."""
    cache = out / 'prepared'
    done = run([shadelab, 'grade', '--prepare', '--exercise', EXERCISE, '--cache', cache / 'solutions'])
    assert re.search(r'solutions: \d+ configurations', done.stdout), done.stdout
    only_cached = re.compile(r'solutions: (\d+) configurations, \1 from the cache, 0 rendered')

    tree = out / 'gradescope-prepared'
    (tree / 'source').mkdir(parents=True)
    (tree / 'source/config.env').write_text(f'EXERCISE={EXERCISE}\n')
    shutil.copytree(cache / 'solutions', tree / 'source/solution-cache')  # where setup.sh leaves it
    (tree / 'submission' / FILE).parent.mkdir(parents=True)
    (tree / 'submission' / FILE).write_text(subs['failing'])
    done = run([repo / 'tools/gradescope/run_autograder'], env=dict(os.environ, AUTOGRADER=str(tree),
                                                                     SHADELAB=str(shadelab)))
    assert only_cached.search(done.stdout), done.stdout
    assert json.loads((tree / 'results/results.json').read_text())['score'] == seen['failing'][0]

    grade = out / 'prairielearn-prepared'
    (grade / 'student').mkdir(parents=True)
    (grade / 'student' / pathlib.Path(FILE).name).write_text(subs['failing'])
    done = run([repo / 'tools/prairielearn/run.sh'],
               env=dict(os.environ, GRADE_ROOT=str(grade), SHADELAB=str(shadelab), EXERCISE=EXERCISE,
                        SOLUTION_CACHE=str(cache / 'solutions')))
    assert only_cached.search(done.stdout), done.stdout
    assert json.loads((grade / 'results/results.json').read_text())['score'] == seen['failing'][2]

    # Classroom 50's runtime image: $SHADELAB_CACHE set (its solutions/ prepared), nothing built.
    checkout = out / 'classroom50' / 'failing'
    env, _ = classroom50_env('failing')
    done = run([sys.executable, out / 'classroom50/autograders/blinn-phong/autograder.py'], cwd=checkout,
               env=dict(env, SHADELAB_CACHE=str(cache)))
    assert only_cached.search(done.stdout), done.stdout
    r = json.loads((checkout / 'result.json').read_text())
    assert r['score'] / r['max-score'] == seen['failing'][1][0], (r, seen['failing'])


def classroom50_course_refused():
    """A course folder in Classroom 50's autograder folder is published where the class reads it: the
    autograder refuses it unless autograder.json says that is meant."""
    grader = out / 'classroom50-course'
    (grader / 'course').mkdir(parents=True)
    shutil.copy(repo / 'tools/classroom50/autograder.py', grader)
    (grader / 'autograder.json').write_text(json.dumps({'exercise': EXERCISE, 'course': 'course'}))
    env, _ = classroom50_env('passing')
    done = subprocess.run([sys.executable, grader / 'autograder.py'], capture_output=True, text=True, env=env,
                          cwd=grader)
    assert done.returncode != 0 and 'course_readable_by_class' in done.stderr, done.stderr
    assert not (grader / 'result.json').exists()


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


def docker_context():
    """The PrairieLearn image's build context leaves a teacher's build/ out (its CMake cache names
    another machine's paths and fails the image's configure step) and keeps what the image builds
    from. Docker's rule: a pattern excludes the paths it matches and everything under them."""
    import fnmatch
    ignore = repo / '.dockerignore'
    patterns = [line.strip() for line in ignore.read_text().splitlines() if line.strip() and line[0] != '#']

    def excluded(path):
        parts = path.split('/')
        return any(fnmatch.fnmatch('/'.join(parts[:n]), p.removeprefix('**/')) or
                   (p.startswith('**/') and fnmatch.fnmatch(parts[n - 1], p[3:]))
                   for p in patterns for n in range(1, len(parts) + 1))
    for path in ('build/CMakeCache.txt', 'build/shadelab', 'build-release/CMakeCache.txt', '.git/HEAD'):
        assert excluded(path), path + ' would be copied into the image'
    for path in ('CMakeLists.txt', 'app/main.cpp', 'exercises/shading/blinn-phong/rubric.json', 'shaders/common/specular.glsl',
                 'tools/prairielearn/run.sh', 'app/cli/grade_class.cpp'):
        assert not excluded(path), path + ' is left out of the image'


def main():
    shutil.rmtree(out, ignore_errors=True)
    out.mkdir(parents=True)
    docker_context()
    subs = submissions()
    seen = {}
    for name, text in subs.items():
        seen[name] = (gradescope(name, text), classroom50(name, text), prairielearn(name, text))
    assert prairielearn('missing', None) is None
    class_csvs(subs)
    platform_downloads(subs)
    prepared_solutions(subs, seen)
    classroom50_course_refused()
    hidden_configuration()
    assert seen['passing'][2] == 1.0 and seen['failing'][2] < 0.7, seen
    maxima = {name: scores[1][1] for name, scores in seen.items()}
    assert len(set(maxima.values())) == 1, ('one max-score for every student of the assignment', maxima)
    print('passed: gradescope, classroom50, prairielearn and moodle/canvas on a passing, a failing and an '
          'ungradable submission; Moodle\'s and Canvas\'s own downloads; each image\'s prepared solutions; '
          'a hidden configuration graded:', json.dumps(seen))


if __name__ == '__main__':
    main()
