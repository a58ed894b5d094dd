#!/usr/bin/env python3
"""CalculiX's own test decks as rsi components (ctest ccx_corpus).

Each deck listed in verification/imports/ccx-corpus.tsv, taken from Debian's
calculix-ccx-test (CalculiX's test suite), is turned into a frequency
problem the way a user would: its model part (every line before the first
*STEP), a *DENSITY added to every *MATERIAL without one, and one step
*FREQUENCY with N modes. ccx's own Lanczos solver gives the reference
eigenvalues (JOB.dat); `rsi modes` on a component case naming the same deck
gives rsi's (rsi runs ccx for K and M, `*FREQUENCY, SOLVER=MATRIXSTORAGE`,
and solves them itself). Each deck's outcome is compared with the one the
data file records:

  agree          rsi exits 0 and every eigenvalue lies within the tolerance
                 below of ccx's;
  refuse         rsi exits 2 and its message holds the recorded fragment;
  exact          ccx's own Lanczos is wrong on the deck (a missed or a
                 spurious eigenvalue: ARPACK on a singular M); rsi exits 0
                 and agrees with an exact dense solve of the matrices ccx
                 stored (the row's fragment, verification/
                 ccx_exact_eigenvalues.m) within exact_tolerances();
  exit3          rsi reports a numerical failure (exit 3) whose message
                 holds the recorded fragment.

Tolerance on eigenvalue j (relative, |lambda_rsi - lambda_ccx| / lambda_ccx):
  5e-7           ccx prints eigenvalues with 7 significant digits
                 (E14.7: half a unit of the 7th digit over a mantissa of at
                 least 0.1);
  + arpack_j     ccx's Lanczos (ARPACK dsaupd, shift-invert about sigma = 1,
                 tol = 1e-2, src/frequencys.f) stops when the residual of a
                 Ritz pair is at most tol |theta|, theta = 1/(lambda - 1);
                 for a symmetric operator the Ritz value is then within
                 min(tol |theta|, (tol theta)^2 / gap) of an eigenvalue
                 (Kato-Temple), gap the distance from theta to the rest of
                 the spectrum, taken from rsi's own eigenvalues (N + 1 of
                 them; a cluster of eigenvalues within 1e-6 of each other
                 counts as one). Relative to lambda: arpack_j =
                 min(tol, tol^2 |theta_j| / gap_j) |lambda_j - 1| / lambda_j.
  + rounding      rsi solves the matrices ccx writes with 14 digits
                 (%20.13e: each entry within a relative 5e-14), ccx's
                 Lanczos the unrounded ones: to first order that moves
                 eigenvalue j by at most 5e-14 (|x|'|K||x| + lambda
                 |x|'|M||x|) / x'Mx, the data file's "rounding" column
                 (the largest over the N modes, computed from the
                 eigenvectors with verification/imports/ccx_rounding_bound.m).
Eigenvalues near zero (rigid-body modes) are compared in absolute terms,
against the same tolerance times the largest eigenvalue compared.

Usage: ccx_corpus.py RSI DATA_FILE WORK_DIR CCX_CACHE [--small] [--survey SPEC...]
  --small   only the rows marked small (the sanitizer build)
  --survey  print the observed outcome of each SPEC, DECK[:VARIANT]@N/NODE
            (N modes, boundary NODE), as a draft row of the data file
            (the outcome and message in place of expected and fragment),
            compare nothing: how the data file was made.
Exits 77 (skipped) when calculix-ccx-test or ccx is absent.
"""

import gzip
import hashlib
import json
import math
import os
import re
import shutil
import subprocess
import sys
from collections import namedtuple

DECKS = '/usr/share/doc/calculix-ccx-test/examples/test'
PRINT_DIGITS = 5e-7
ARPACK_TOL = 1e-2
CLUSTER = 1e-6
EXACT_PRINT = 5e-13

# One eigenvalue of `rsi modes` (modes.csv): lambda = (2 pi f)^2, the square
# of its uncertainty_hz on a rigid-body mode (f = 0 +- u), and rigid_body.
Eigenvalue = namedtuple('Eigenvalue', 'value uncertainty rigid')

# Element types and their node counts, for the variants that turn a deck's
# quadratic elements into linear ones (first nodes = corner nodes).
NODE_COUNT = {
    'C3D4': 4, 'C3D10': 10, 'C3D6': 6, 'C3D15': 15, 'C3D8': 8, 'C3D8R': 8, 'C3D8I': 8,
    'C3D20': 20, 'C3D20R': 20, 'CPS3': 3, 'CPS6': 6, 'CPS4': 4, 'CPS4R': 4, 'CPS8': 8,
    'CPS8R': 8, 'CPE3': 3, 'CPE6': 6, 'CPE4': 4, 'CPE4R': 4, 'CPE8': 8, 'CPE8R': 8,
    'CAX3': 3, 'CAX6': 6, 'CAX4': 4, 'CAX4R': 4, 'CAX8': 8, 'CAX8R': 8, 'S3': 3, 'S6': 6,
    'S4': 4, 'S4R': 4, 'S8': 8, 'S8R': 8, 'B31': 2, 'B31R': 2, 'B32': 3, 'B32R': 3,
}

MATERIAL_KEYWORDS = (
    '*ELASTIC', '*DENSITY', '*EXPANSION', '*PLASTIC', '*CONDUCTIVITY', '*SPECIFICHEAT',
    '*HYPERELASTIC', '*HYPERFOAM', '*USERMATERIAL', '*DEPVAR', '*CREEP', '*DAMPING',
    '*DEFORMATIONPLASTICITY', '*ELECTRICALCONDUCTIVITY', '*FLUIDCONSTANTS',
    '*SPECIFICGASCONSTANT', '*CYCLICHARDENING', '*RATEDEPENDENT', '*MAGNETICPERMEABILITY')


def squash(line):
    """A deck line as ccx reads it: blanks and tabs removed, upper case."""
    return re.sub(r'[ \t]', '', line).upper()


def deck_text(name):
    plain = os.path.join(DECKS, name + '.inp')
    if os.path.exists(plain):
        with open(plain, encoding='latin-1') as f:
            return f.read()
    with gzip.open(plain + '.gz', 'rt', encoding='latin-1') as f:
        return f.read()


def element_types(lines):
    types = []
    for line in lines:
        s = squash(line)
        if s.startswith('*ELEMENT') and not s.startswith('*ELEMENTOUTPUT'):
            m = re.search(r',TYPE=([A-Z0-9]+)', s)
            if m and m.group(1) not in types:
                types.append(m.group(1))
    return types


def features(lines):
    """The keywords of the model part besides nodes, elements, sets, sections, materials."""
    plain = {'NODE', 'ELEMENT', 'NSET', 'ELSET', 'MATERIAL', 'ELASTIC', 'DENSITY',
             'SOLIDSECTION', 'BOUNDARY', 'HEADING', 'SHELLSECTION', 'BEAMSECTION'}
    found = []
    for line in lines:
        s = squash(line)
        if s.startswith('*') and not s.startswith('**'):
            key = s[1:].split(',')[0]
            if key == 'NSET' and ',GENERATE' in s:
                key = 'NSETGENERATE'
            if key not in plain and key not in found:
                found.append(key)
    return found


def substitute(lines, source, target):
    """Elements of type `source` rewritten as `target`, keeping their first nodes."""
    keep = NODE_COUNT[target]
    width = NODE_COUNT[source]
    out, fields, inside = [], [], False
    for line in lines:
        s = squash(line)
        if s.startswith('*') and not s.startswith('**'):
            inside = s.startswith('*ELEMENT') and re.search(r',TYPE=' + source + r'(,|$)', s) is not None
            if inside:
                line = re.sub(r'(?i)(type\s*=\s*)' + source + r'\b', r'\g<1>' + target, line)
            out.append(line)
            continue
        if not inside or not s or s.startswith('**'):
            out.append(line)
            continue
        fields += [f for f in s.split(',') if f != '']
        if len(fields) >= width + 1:
            out.append(', '.join(fields[:keep + 1]))
            fields = fields[width + 1:]
    return out


def add_densities(lines):
    out = []
    for i, line in enumerate(lines):
        out.append(line)
        if not squash(line).startswith('*MATERIAL'):
            continue
        has = False
        for later in lines[i + 1:]:
            s = squash(later)
            if not s.startswith('*') or s.startswith('**'):
                continue
            if not s.startswith(MATERIAL_KEYWORDS):
                break
            has = has or s.startswith('*DENSITY')
        if not has:
            out += ['*DENSITY', '1.']
    return out


def split_includes(lines):
    """The *NODE and *ELEMENT blocks moved to included files, two levels deep:
    the deck includes mesh/all.inp, which includes mesh/nodes.inp and
    mesh/elements.inp, named relative to the deck's folder (ccx's working
    directory), not to mesh/. Returns (deck lines, {file: text})."""
    deck, nodes, elements, target, placed = [], [], [], None, False
    for line in lines:
        s = squash(line)
        if s.startswith('*') and not s.startswith('**'):
            target = None
            if s.startswith('*NODE') and not s.startswith(('*NODEPRINT', '*NODEFILE', '*NODEOUTPUT')):
                target = nodes
            elif s.startswith('*ELEMENT') and not s.startswith('*ELEMENTOUTPUT'):
                target = elements
            if target is not None and not placed:
                deck.append('*INCLUDE, INPUT=mesh/all.inp')
                placed = True
        (target if target is not None else deck).append(line)
    files = {'mesh/all.inp': '*INCLUDE, INPUT=mesh/nodes.inp\n*INCLUDE, INPUT=mesh/elements.inp\n',
             'mesh/nodes.inp': '\n'.join(nodes) + '\n',
             'mesh/elements.inp': '\n'.join(elements) + '\n'}
    return deck, files


def frequency_deck(deck, variant, modes):
    """The deck as a frequency problem: (main text, {included file: text},
    element types, features)."""
    lines = deck_text(deck).replace('\r', '').split('\n')
    model = []
    for line in lines:
        if squash(line).startswith('*STEP'):
            break
        model.append(line)
    files = {}
    feats = features(model)
    if variant == 'include':
        model, files = split_includes(model)
        feats.append('INCLUDE')
    elif variant != '-':
        source, target = variant.split('>')
        model = substitute(model, source, target)
    types = element_types(model + [l for t in files.values() for l in t.split('\n')])
    model = add_densities(model)
    text = '\n'.join(model + ['*STEP', '*FREQUENCY', str(modes), '*END STEP']) + '\n'
    return text, files, types, feats


def write_files(folder, main, text, files):
    with open(os.path.join(folder, main), 'w', encoding='latin-1') as f:
        f.write(text)
    for name, body in files.items():
        os.makedirs(os.path.dirname(os.path.join(folder, name)), exist_ok=True)
        with open(os.path.join(folder, name), 'w', encoding='latin-1') as f:
            f.write(body)


def ccx_eigenvalues(text, files, cache, tag):
    """ccx's eigenvalues of the deck `text` (with its included files), run in
    its own folder and cached by the texts' hash."""
    digest = hashlib.sha1(text.encode('latin-1'))
    for name in sorted(files):
        digest.update(name.encode() + b'\0' + files[name].encode('latin-1'))
    entry = os.path.join(cache, 'corpus-%s-%s' % (tag, digest.hexdigest()[:16]))
    if not os.path.isdir(entry):
        work = entry + '.tmp%d' % os.getpid()
        shutil.rmtree(work, ignore_errors=True)
        os.makedirs(work)
        write_files(work, 'job.inp', text, files)
        with open(os.path.join(work, 'ccx.log'), 'w') as log:
            status = subprocess.call(['ccx', '-i', 'job'], cwd=work, stdout=log, stderr=log)
        with open(os.path.join(work, 'ccx.log'), encoding='latin-1') as log:
            errors = [line.strip() for line in log if '*ERROR' in line]
        if status != 0 or errors:
            # ARPACK's errors (too many modes for the model) exit 0 with zeros.
            shutil.rmtree(work, ignore_errors=True)
            return None, 'ccx exit %d %s' % (status, ' '.join(errors[:2]))
        os.rename(work, entry)
    values = []
    with open(os.path.join(entry, 'job.dat'), encoding='latin-1') as f:
        started = False
        for line in f:
            if 'E I G E N V A L U E   O U T P U T' in line:
                if started:
                    break
                started = True
                continue
            fields = line.split()
            if started and len(fields) >= 2 and fields[0].isdigit():
                values.append(float(fields[1]))
    return values, ''


def rsi_eigenvalues(rsi, work, deck, text, files, boundary, modes, cache):
    """rsi modes on a component case naming the deck: (exit, stderr, eigenvalues)."""
    folder = os.path.join(work, re.sub(r'[^A-Za-z0-9]', '-', deck))
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    write_files(folder, 'deck.inp', text, files)
    case = {'component': {'name': 'corpus', 'source': {'calculix_deck': 'deck.inp'},
                          'boundary': {'nodes': boundary}, 'units': 'the deck\'s'}}
    with open(os.path.join(folder, 'case.json'), 'w') as f:
        json.dump(case, f)
    run = subprocess.run([rsi, 'modes', os.path.join(folder, 'case.json'), '--count', str(modes),
                          '--out', os.path.join(folder, 'out'), '--ccx-cache', cache],
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, universal_newlines=True)
    values = []
    if run.returncode == 0:
        with open(os.path.join(folder, 'out', 'modes.csv')) as f:
            header = next(f).strip().split(',')
            hz_at, u_at, rigid_at = (header.index(k) for k in
                                     ('frequency_hz', 'uncertainty_hz', 'rigid_body'))
            for line in f:
                fields = line.strip().split(',')
                values.append(Eigenvalue((2.0 * math.pi * float(fields[hz_at])) ** 2,
                                         (2.0 * math.pi * float(fields[u_at])) ** 2,
                                         fields[rigid_at] == '1'))
    return run.returncode, run.stderr.strip(), values


def tolerances(reference, spectrum, rounding):
    """Per-mode relative tolerance (module docstring); spectrum: rsi's N+1 eigenvalues."""
    theta = [1.0 / (lam - 1.0) if lam != 1.0 else math.inf for lam in spectrum]
    out = []
    for j, lam in enumerate(reference):
        gap = math.inf
        for k, other in enumerate(theta):
            if k != j and abs(spectrum[k] - spectrum[j]) > CLUSTER * max(abs(spectrum[j]), 1e-300):
                gap = min(gap, abs(other - theta[j]))
        t = abs(theta[j])
        arpack = min(ARPACK_TOL * t, (ARPACK_TOL * t) ** 2 / gap) if gap > 0 else ARPACK_TOL * t
        arpack_rel = arpack / t if t > 0 else ARPACK_TOL
        out.append(PRINT_DIGITS + arpack_rel * abs(lam - 1.0) / max(abs(lam), 1e-300) + rounding)
    return out


def compare(reference, computed, tol):
    """(worst ratio error/tolerance, worst relative error, detail) over the reference modes.

    tol[j] is relative; eigenvalues near zero are compared against tol[j] times the largest
    reference eigenvalue; a mode rsi reports as rigid (zero within its uncertainty u_j,
    modes.csv) agrees when |reference_j| <= u_j + tol[j] * scale: rsi claims no more."""
    n = len(reference)
    scale = max(abs(v) for v in reference)
    worst, worst_rel, where = 0.0, 0.0, ''
    for j in range(n):
        lam = computed[j]
        if lam.rigid:
            err = abs(reference[j])
            rel = err / max(scale, 1e-300)
            ratio = err / (lam.uncertainty + tol[j] * scale)
            text = 'rsi rigid (0 +- %.3g)' % lam.uncertainty
        else:
            err = abs(lam.value - reference[j])
            small = abs(reference[j]) <= 1e-6 * scale
            rel = err / max(scale, 1e-300) if small else err / abs(reference[j])
            ratio = rel / tol[j]
            text = 'rsi %.9g' % lam.value
        worst_rel = max(worst_rel, rel)
        if ratio > worst or not where:
            worst, where = ratio, 'mode %d: %s ccx %.7g rel %.2e tol %.2e' % (
                j + 1, text, reference[j], rel, tol[j])
    return worst, worst_rel, where


def exact_reference(fragment):
    """An `exact` row's fragment, 'n=DOFS LAMBDA...': (dofs, eigenvalues)."""
    fields = fragment.split()
    return int(fields[0][2:]), [float(v) for v in fields[1:]]


def exact_tolerances(dofs, count, rounding):
    """rsi and the exact solve (Octave eig, verification/imports/ccx_exact_eigenvalues.m) solve the same
    stored matrices, so the input's rounding is common to both; each solver is backward stable
    (LAPACK Users' Guide, 3rd ed., 4.7), to a relative perturbation of the entries of at most
    max(5e-14, n eps), and the rounding column is the first-order effect of 5e-14 on the
    eigenvalues: two solvers, 2 rounding max(1, n eps / 5e-14), plus the printed 13 digits."""
    eps = 2.0 ** -52
    return [EXACT_PRINT + 2.0 * rounding * max(1.0, dofs * eps / 5e-14)] * count


def read_rows(path):
    rows = []
    with open(path) as f:
        for number, line in enumerate(f, 1):
            if not line.strip() or line.startswith('#'):
                continue
            fields = line.rstrip('\n').split('\t')
            if len(fields) != 10:
                sys.exit('%s:%d: expected 10 tab-separated fields, got %d' % (path, number, len(fields)))
            deck, variant, modes, boundary, types, feats, small, expected, fragment, rounding = fields
            if expected in ('agree', 'exact') and rounding == '-':
                sys.exit('%s:%d: an agree row needs its rounding bound' % (path, number))
            rows.append(dict(deck=deck, variant=variant, modes=int(modes),
                             boundary=[int(b) for b in boundary.split(',')], types=types,
                             features=feats, small=small == 'small', expected=expected,
                             fragment=fragment, line=number,
                             rounding=0.0 if rounding == '-' else float(rounding)))
    return rows


def run_row(rsi, work, cache, row):
    """The observed outcome of one row: (status, detail, types, features, relerr)."""
    name = row['deck'] + ('' if row['variant'] == '-' else ':' + row['variant'])
    text, files, types, feats = frequency_deck(row['deck'], row['variant'], row['modes'])
    status, stderr, computed = rsi_eigenvalues(rsi, work, name, text, files, row['boundary'],
                                               row['modes'] + 1, cache)
    if status == 0:
        if len(computed) < row['modes'] + 1:
            return 'disagree', 'rsi gave %d eigenvalues, %d asked' % (
                len(computed), row['modes'] + 1), types, feats, None
        values = [lam.value for lam in computed]
        if row.get('expected') == 'exact':
            dofs, reference = exact_reference(row['fragment'])
            tol = exact_tolerances(dofs, len(reference), row['rounding'])
        else:
            reference, why = ccx_eigenvalues(text, files, cache,
                                              re.sub(r'[^A-Za-z0-9]', '-', name))
            if reference is None:
                return 'ccx-fails', why, types, feats, None
            reference = reference[:row['modes']]
            tol = tolerances(reference, values, row.get('rounding', 0.0))
        worst, rel, where = compare(reference, computed, tol)
        return ('agree' if worst <= 1.0 else 'disagree'), where, types, feats, rel
    kind = {2: 'refuse', 3: 'exit3'}.get(status, 'exit%d' % status)
    return kind, stderr, types, feats, None


def main():
    args = sys.argv[1:]
    small = '--small' in args
    args = [a for a in args if a != '--small']
    survey = None
    if '--survey' in args:
        at = args.index('--survey')
        survey, args = args[at + 1:], args[:at]
    if len(args) != 4:
        sys.exit(__doc__)
    rsi, data, work, cache = args
    if not os.path.isdir(DECKS):
        print('SKIP: %s absent (Debian package calculix-ccx-test)' % DECKS)
        return 77
    if shutil.which('ccx') is None:
        print('SKIP: ccx absent (Debian package calculix-ccx)')
        return 77
    os.makedirs(work, exist_ok=True)
    os.makedirs(cache, exist_ok=True)
    if survey is not None:
        for item in survey:
            # DECK[:FROM>TO]@MODES/NODE[,NODE..]
            name, _, spec = item.partition('@')
            deck, _, variant = name.partition(':')
            modes, _, boundary = spec.partition('/')
            row = dict(deck=deck, variant=variant or '-', modes=int(modes),
                       boundary=[int(b) for b in boundary.split(',')])
            status, detail, types, feats, rel = run_row(rsi, work, cache, row)
            print('\t'.join([row['deck'], row['variant'], str(row['modes']),
                             ','.join(map(str, row['boundary'])), ' '.join(types),
                             ' '.join(feats) or '-', '-', status,
                             detail.replace('\n', ' ')[:300] if detail else '-',
                             '%.2e' % rel if rel is not None else '-']), flush=True)
        return 0
    rows = read_rows(data)
    if small:
        rows = [r for r in rows if r['small']]
    failures = []
    counts = {}
    for row in rows:
        name = row['deck'] + ('' if row['variant'] == '-' else ':' + row['variant'])
        status, detail, types, feats, rel = run_row(rsi, work, cache, row)
        expected = row['expected']
        ok = (' '.join(types) == row['types'] and (' '.join(feats) or '-') == row['features'])
        why = '' if ok else 'recorded types/features "%s" / "%s", the deck has "%s" / "%s"' % (
            row['types'], row['features'], ' '.join(types), ' '.join(feats) or '-')
        if expected == 'agree':
            ok = ok and status == 'agree'
        elif expected == 'refuse':
            ok = ok and status == 'refuse' and row['fragment'] in detail
        elif expected == 'exact':
            ok = ok and status == 'agree'
        elif expected == 'exit3':
            ok = ok and status == 'exit3' and row['fragment'] in detail
        elif expected == 'exit3|agree':
            # A deck at the edge of rsi's self-check (the tsv header): the
            # refusal naming the check, or certified modes that agree.
            ok = ok and ((status == 'exit3' and row['fragment'] in detail) or status == 'agree')
        else:
            ok, why = False, 'unknown expected outcome %r' % expected
        counts[expected] = counts.get(expected, 0) + 1
        print('%-28s %-22s %-14s %-10s %s%s' % (
            name, row['types'], expected, status,
            ('max rel %.2e; ' % rel) if rel is not None else '', detail[:240]), flush=True)
        if not ok:
            failures.append('%s (line %d): expected %s%s, got %s: %s %s' % (
                name, row['line'], expected,
                (' "' + row['fragment'] + '"') if row['fragment'] != '-' else '', status,
                detail[:300], why))
    print('%d decks: %s' % (len(rows), ', '.join('%d %s' % (v, k) for k, v in sorted(counts.items()))))
    for f in failures:
        print('FAIL: ' + f)
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
