#!/usr/bin/env python3
"""Classroom 50's autograder for one ShadeLab exercise.

Classroom 50's runner calls it once per submission, in the student's checkout, with the
submission's identity in the environment (CLASSROOM, ASSIGNMENT, OWNER, SUBMISSION_TAG, COMMIT_URL,
RELEASE_URL, REVIEW_URL, ASSIGNMENT_TYPE). It grades the student's shader folder headless
(OSMesa, no GPU, no display) with `shadelab grade --format classroom50` and leaves in the checkout:

  result.json              the grade, schema classroom50/result/v1 (points scaled to whole numbers)
  release-body.md          the release's text: score, diagnosis, a line per check, and the failing
                           configurations' pictures, each linked to the release asset of its name
  shadelab-report.html     the full report, each failing configuration's three pictures inside it
  shadelab-pictures.zip    the student's frames, the solution's and their differences, as PNG files
  *.png                    each picture the release body shows, to be attached under its own name

`autograder.py --release-assets` prints the assignment's release_assets: the two files above and
every picture the exercise can show (three per configuration), so that each submission's release
carries what its body links. Beside this file, autograder.json says what to grade:

  {"exercise": "shading/blinn-phong",   the exercise, LAB/NAME
   "shaders": "shaders",                 the student's shader folder in their repository (else the
                                         checkout itself: a flat upload is placed as well)
   "course": "course",                   optional: a course folder beside this file (--exercises),
   "course_readable_by_class": true,     which the class can read (this folder is published): taken
                                         only with this line, which says so
   "shadelab_git": URL, "shadelab_ref": REF}   optional: your course's copy of ShadeLab, cloned
                                         and built where $SHADELAB names no built binary

Run in ShadeLab's runtime image (tools/classroom50/Dockerfile: $SHADELAB and $SHADELAB_CACHE set,
the built-in exercises' solutions drawn when the image was built), a submission builds nothing and
draws only the student's frames. `autograder.py --runtime IMAGE` prints the assignment's runtime
block for that image.

Exit 0 when a result was written, pass or fail; non-zero only when grading itself could not run
(Classroom 50 then reports an error).
"""
import datetime
import json
import os
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile
import zipfile

HERE = pathlib.Path(__file__).resolve().parent


def fail(message):
    print(f"::error::{message}", file=sys.stderr)
    sys.exit(1)


def commit_date():
    """The graded commit's committer date in UTC: the same on every regrade of that commit."""
    try:
        seconds = subprocess.run(['git', 'log', '-1', '--format=%ct', 'HEAD'], capture_output=True, text=True,
                                 check=True).stdout.strip()
        stamp = datetime.datetime.fromtimestamp(int(seconds), datetime.timezone.utc)
        return stamp.strftime('%Y-%m-%dT%H:%M:%SZ')
    except (OSError, subprocess.CalledProcessError, ValueError):
        return None


def shadelab_binary(config):
    if os.environ.get('SHADELAB'):
        return os.environ['SHADELAB']
    source = HERE / 'shadelab-src'
    if not source.is_dir():
        if 'shadelab_git' not in config:
            fail('no ShadeLab to grade with: set $SHADELAB to a built shadelab binary, or "shadelab_git" in '
                 'autograder.json to the URL of your course\'s copy of ShadeLab')
        subprocess.run(['git', 'clone', '--depth', '1', '--branch', config.get('shadelab_ref', 'main'),
                        config['shadelab_git'], str(source)], check=True)
    build = source / 'build'
    subprocess.run(['cmake', '-S', str(source), '-B', str(build), '-G', 'Ninja', '-DCMAKE_BUILD_TYPE=Release',
                    '-DSHADELAB_TESTS=OFF', '-DSHADELAB_BENCH=OFF'], check=True, stdout=subprocess.DEVNULL)
    subprocess.run(['cmake', '--build', str(build), '--target', 'shadelab'], check=True)
    return str(build / 'shadelab')


def slug(text):
    """grade's file names from ids and configuration names: "shading/blinn-phong" -> "shading-blinn-phong"."""
    return ''.join(c.lower() if c.isascii() and c.isalnum() else '-' for c in text)


def release_assets(config, shadelab):
    """What the assignment's release_assets lists: the report, the pictures' zip, and the three
    pictures of every configuration of the exercise's rubric, by the names grade gives them."""
    roots = [HERE / config['course']] if config.get('course') else []
    roots.append(pathlib.Path(shadelab).resolve().parent.parent / 'exercises')
    rubric = next((r / config['exercise'] / 'rubric.json' for r in roots
                   if (r / config['exercise'] / 'rubric.json').is_file()), None)
    if rubric is None:
        fail(f"no exercise {config['exercise']} in " + ', '.join(str(r) for r in roots))
    assets = ['shadelab-report.html', 'shadelab-pictures.zip']
    for i, c in enumerate(json.loads(rubric.read_text())['configurations']):
        stem = f"{slug(config['exercise'])}-{i + 1}-{slug(c['name'])}"
        assets += [f'{stem}-student.png', f'{stem}-solution.png', f'{stem}-diff.png']
    return assets


def asset_url(name):
    """Where the release serves its asset `name`: RELEASE_URL's /releases/tag/TAG as /releases/download/TAG."""
    release = os.environ.get('RELEASE_URL', '')
    if '/releases/tag/' in release:
        return release.replace('/releases/tag/', '/releases/download/', 1).rstrip('/') + '/' + name
    server, repository, tag = (os.environ.get(k, '') for k in ('GITHUB_SERVER_URL', 'GITHUB_REPOSITORY',
                                                                 'SUBMISSION_TAG'))
    if server and repository and tag:
        return f'{server}/{repository}/releases/download/{tag}/{name}'
    return name


def main():
    try:
        config = json.loads((HERE / 'autograder.json').read_text())
    except (OSError, ValueError) as e:
        fail(f'autograder.json beside the autograder: {e}')
    if 'exercise' not in config:
        fail('autograder.json: "exercise" is missing (LAB/NAME, e.g. shading/blinn-phong)')
    if config.get('course') and config.get('course_readable_by_class') is not True:
        fail('autograder.json names a course folder: everything beside autograder.py is published where the '
             'class can read it, the rubrics\' solutions and right answers included. Add '
             '"course_readable_by_class": true if that is meant, else grade that course elsewhere '
             '(docs/courses.md, "Classroom 50")')
    if len(sys.argv) == 3 and sys.argv[1] == '--runtime':
        print(json.dumps({'runs-on': 'ubuntu-latest', 'container': {'image': sys.argv[2], 'user': 'root'}}, indent=2))
        return 0
    if sys.argv[1:] == ['--release-assets']:
        print(json.dumps(release_assets(config, shadelab_binary(config))))
        return 0
    env = dict(os.environ, LIBGL_ALWAYS_SOFTWARE='1')
    if 'COMMIT_DATE' not in env:
        date = commit_date()
        if date:
            env['COMMIT_DATE'] = date
    # The student's shader folder, or the checkout itself where they have none: `grade --class` on a
    # class of this one upload places each of the rubric's files (by path, by name, by name in any
    # case; a zip unpacked) and says what it took, ignored or could not find.
    shaders = pathlib.Path(config.get('shaders', 'shaders'))
    upload = shaders if shaders.is_dir() else pathlib.Path('.')
    out = pathlib.Path(tempfile.mkdtemp(prefix='shadelab-'))
    (out / 'class').mkdir()
    (out / 'class' / 'submission').symlink_to(upload.resolve(), target_is_directory=True)
    # In the runtime image the solutions were drawn when it was built ($SHADELAB_CACHE): the
    # submission draws only the student's frames. Elsewhere they are drawn for this submission.
    cache = [] if os.environ.get('SHADELAB_CACHE') else ['--no-cache']
    command = [shadelab_binary(config), 'grade', '--class', str(out / 'class'), '--exercise', config['exercise'],
               '--format', 'classroom50', '--out', str(out / 'grades')] + cache
    if config.get('course'):
        command += ['--exercises', str(HERE / config['course'])]
    graded = subprocess.run(command, env=env)
    report = out / 'grades' / 'students' / 'submission'
    if (report / 'grade.log').is_file():
        print((report / 'grade.log').read_text())
    if graded.returncode not in (0, 1) or not (report / 'result.json').is_file():
        fail(f'shadelab grade could not grade this submission (exit {graded.returncode}); the log above says why')

    shutil.copy(report / 'result.json', 'result.json')
    shutil.copy(report / 'report.html', 'shadelab-report.html')
    with zipfile.ZipFile('shadelab-pictures.zip', 'w', zipfile.ZIP_DEFLATED) as pictures:
        for png in sorted(report.glob('*.png')):
            pictures.write(png, png.name)
    result = json.loads((report / 'result.json').read_text())
    points = json.loads((report / 'report.json').read_text())
    total = sum(e.get('total', 0) for e in points.get('exercises', []))
    scale = result['max-score'] / total if total else 1
    body = f"**{result['score']} / {result['max-score']}**"
    if round(scale) != 1:
        body += f" (ShadeLab's points x{round(scale)}, so that every check is whole)"
    # Each picture the report shows, attached to the release under its own name and linked there:
    # a bare file name in a release's text resolves to nothing.
    pictures = []

    def attached(match):
        name = match.group(2)
        if not (report / name).is_file():
            return match.group(0)
        shutil.copy(report / name, name)
        pictures.append(name)
        return f'![{match.group(1)}]({asset_url(name)})'

    body += '\n\n' + re.sub(r'!\[([^\]]*)\]\(([^)\s]+)\)', attached, (report / 'report.md').read_text())
    body += (f"\nThe full report with its pictures: [shadelab-report.html]({asset_url('shadelab-report.html')}); "
             f"the pictures alone: [shadelab-pictures.zip]({asset_url('shadelab-pictures.zip')}).\n")
    pathlib.Path('release-body.md').write_text(body)
    shutil.rmtree(out, ignore_errors=True)
    print(f"ShadeLab: {result['score']} / {result['max-score']} points")
    return 0


if __name__ == '__main__':
    sys.exit(main())
