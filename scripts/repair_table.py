#!/usr/bin/env python3
"""Runs `meshedit repair` and `check --problems` on real meshes and prints a markdown table.

Usage: scripts/repair_table.py MESHEDIT [--fair] [FILES...]
Without FILES: every mesh of /usr/share/assimp/models (assimp-testmodels) and of CGAL's demo
data (data/meshes/*.off, *.ply from /usr/share/doc/libcgal-dev/data.tar.gz).
"""
import os, re, subprocess, sys, tarfile, tempfile, time

EXTS = ('.obj', '.off', '.ply', '.stl', '.gltf', '.glb', '.dae')
LIMIT = 60  # seconds per command, so nothing hangs


def inputs(tmp):
    files = []
    for root, _, names in os.walk('/usr/share/assimp/models'):
        files += [os.path.join(root, n) for n in sorted(names) if n.lower().endswith(EXTS)]
    tar = '/usr/share/doc/libcgal-dev/data.tar.gz'
    if os.path.exists(tar):
        with tarfile.open(tar) as t:
            for m in t.getmembers():
                if re.search(r'data/meshes/[^/]+\.(off|ply)$', m.name) and m.isfile():
                    t.extract(m, tmp)
                    files.append(os.path.join(tmp, m.name))
    return sorted(files)


def run(cmd):
    try:
        p = subprocess.run(cmd, capture_output=True, text=True, errors='replace', timeout=LIMIT)
        return p.returncode, p.stdout, p.stderr
    except subprocess.TimeoutExpired:
        return None, '', f'timed out after {LIMIT} s'


def reason(err, path):
    # The last line of stderr without the "meshedit: PATH: " prefix, safe in a table cell.
    line = err.strip().splitlines()[-1] if err.strip() else '?'
    line = line.replace('meshedit: ', '', 1).replace(path + ': ', '', 1)
    return line[:110].replace('|', '\\|')


def summary(out):
    lines = [l for l in out.strip().splitlines() if l]
    return lines[-1].split(': ', 1)[-1] if lines else ''


def counts(err):
    # What repair did, from its one line per step.
    got = []
    for word, pat in (('merged', r'merged (\d+) vertices'), ('degenerate', r'removed (\d+) degenerate'),
                      ('duplicate', r'removed (\d+) duplicate'),
                      ('stitched', r'stitched (\d+) boundary'), ('turned', r'turned over (\d+)'),
                      ('small', r'removed (\d+) components?'), ('filled', r'filled (\d+)')):
        m = re.search(pat, err)
        if m:
            got.append(f'{word} {m.group(1)}')
    return ', '.join(got) or 'nothing'


def info(me, path):
    _, out, _ = run([me, 'info', path])
    get = lambda k: (re.search(rf'^{k}:\s+(\d+)', out, re.M) or [None, '?'])[1]
    return get('faces'), get('boundary loops'), get('components')


def row(me, path, extra, tmp):
    name = os.path.relpath(path, '/usr/share/assimp/models') if path.startswith('/usr') \
        else 'cgal:' + os.path.basename(path)
    rc, before, err = run([me, 'check', path, '--problems'])
    faces, _, _ = info(me, path)
    if rc is None or faces == '?':
        return f'| {name} | – | not loaded: {reason(err, path)} |||||||'
    out1, out2 = os.path.join(tmp, 'r1.ply'), os.path.join(tmp, 'r2.ply')
    t = time.time()
    rc, _, err = run([me, 'repair', path, out1] + extra)
    took = time.time() - t
    if rc != 0:
        return f'| {name} | {faces} | failed ({rc}): {reason(err, path)} |||||| {took:.2f} |'
    rc2, after, _ = run([me, 'check', out1, '--problems'])
    valid = 'yes' if 'INVALID' not in after and rc2 is not None else 'no'
    _, loops, comps = info(me, out1)
    run([me, 'repair', out1, out2] + extra)
    same = 'yes' if os.path.exists(out2) and open(out1, 'rb').read() == open(out2, 'rb').read() else 'no'
    return (f'| {name} | {faces} | {counts(err)} | {summary(before)} | {summary(after)} | {valid} | '
            f'{"yes" if loops == "0" else "no (" + loops + " loops)"} | {same} | {took:.2f} |')


def main():
    me = sys.argv[1]
    extra = ['--fill-holes', '1000', '--fair'] if '--fair' in sys.argv[2:] else []
    with tempfile.TemporaryDirectory() as tmp:
        files = [a for a in sys.argv[2:] if a != '--fair'] or inputs(tmp)
        print('| file | faces | repair did | problems before | problems after | valid | watertight | unchanged by 2nd repair | time (s) |')
        print('|---|---|---|---|---|---|---|---|---|')
        for f in files:
            print(row(me, f, extra, tmp), flush=True)


if __name__ == '__main__':
    main()
