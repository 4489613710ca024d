#!/usr/bin/env python3
"""Classroom 50's autograder for one ShadeLab exercise.

Classroom 50's runner calls it once per submission, in the student's checkout, with the
submission's identity in the environment (CLASSROOM, ASSIGNMENT, OWNER, SUBMISSION_TAG, COMMIT_URL,
RELEASE_URL, REVIEW_URL, ASSIGNMENT_TYPE). It grades the student's shader folder headless
(OSMesa, no GPU, no display) with `shadelab grade --format classroom50` and leaves in the checkout:

  result.json              the grade, schema classroom50/result/v1 (points scaled to whole numbers)
  release-body.md          the release's text: score, diagnosis and a line per check
  shadelab-report.html     the full report, each failing configuration's three pictures inside it
  shadelab-pictures.zip    the student's frames, the solution's and their differences, as PNG files

List the last two in the assignment's release_assets so that each submission's release carries
them. Beside this file, autograder.json says what to grade:

  {"exercise": "shading/blinn-phong",   the exercise, LAB/NAME
   "shaders": "shaders",                 the student's shader folder in their repository
   "course": "course",                   optional: a course folder beside this file (--exercises)
   "shadelab_git": URL, "shadelab_ref": REF}   where ShadeLab's source is cloned from and built

$SHADELAB (a built binary) skips the build. Exit 0 when a result was written, pass or fail;
non-zero only when grading itself could not run (Classroom 50 then reports an error).
"""
import datetime
import json
import os
import pathlib
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
            fail('autograder.json names no shadelab_git to build ShadeLab from, and $SHADELAB is not set')
        subprocess.run(['git', 'clone', '--depth', '1', '--branch', config.get('shadelab_ref', 'main'),
                        config['shadelab_git'], str(source)], check=True)
    build = source / 'build'
    subprocess.run(['cmake', '-S', str(source), '-B', str(build), '-G', 'Ninja', '-DCMAKE_BUILD_TYPE=Release',
                    '-DSHADELAB_TESTS=OFF', '-DSHADELAB_BENCH=OFF'], check=True, stdout=subprocess.DEVNULL)
    subprocess.run(['cmake', '--build', str(build), '--target', 'shadelab'], check=True)
    return str(build / 'shadelab')


def main():
    try:
        config = json.loads((HERE / 'autograder.json').read_text())
    except (OSError, ValueError) as e:
        fail(f'autograder.json beside the autograder: {e}')
    if 'exercise' not in config:
        fail('autograder.json: "exercise" is missing (LAB/NAME, e.g. shading/blinn-phong)')
    env = dict(os.environ, LIBGL_ALWAYS_SOFTWARE='1')
    if 'COMMIT_DATE' not in env:
        date = commit_date()
        if date:
            env['COMMIT_DATE'] = date
    shaders = pathlib.Path(config.get('shaders', 'shaders'))
    out = pathlib.Path(tempfile.mkdtemp(prefix='shadelab-'))
    command = [shadelab_binary(config), 'grade', '--exercise', config['exercise'], '--shaders', str(shaders),
               '--format', 'classroom50', '--out', str(out / 'report'), '--no-cache']
    if config.get('course'):
        command += ['--exercises', str(HERE / config['course'])]
    graded = subprocess.run(command, env=env)
    report = out / 'report'
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
    body += '\n\n' + (report / 'report.md').read_text()
    body += '\nThe full report with its pictures: shadelab-report.html; the pictures alone: shadelab-pictures.zip.\n'
    pathlib.Path('release-body.md').write_text(body)
    shutil.rmtree(out, ignore_errors=True)
    print(f"ShadeLab: {result['score']} / {result['max-score']} points")
    return 0


if __name__ == '__main__':
    sys.exit(main())
