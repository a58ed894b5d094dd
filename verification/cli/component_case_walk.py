#!/usr/bin/python3
"""Walks the component-case schema (issue "Hardening, third round"): for
every key data/README.md lists for a component case, a variant of a base
case changes that key, rsi runs the commands the key feeds, and the output
(modes, history bytes, the summary without its timings, the exported files,
the campaign tables) or the message must change. A key whose change changes
nothing is read and ignored: a defect (fix it or refuse the key). Free-text
keys (description, notes) are exempt, and said so.

The keys are taken from data/README.md's table (every backticked key of
its first column in the section "Component case files"), so a key
documented without a variant here fails the walk.

Usage: component_case_walk.py RSI SOURCE_DIR WORK CCX_CACHE
Runs on a two-brick CalculiX deck (24 dofs, ccx about 0.05 s; written
here) for every key but the gmsh blade's, and on the gmsh blade's coarse
default (4,101 dofs) for those, through `rsi export` (K, M and node
coordinates: a translated or turned blade has the same frequencies).
"""
import copy
import csv
import hashlib
import io
import json
import os
import re
import shutil
import subprocess
import sys

RSI, SRC, WORK, CACHE = sys.argv[1:5]
os.makedirs(WORK, exist_ok=True)

BRICK = """** two C3D8 bricks along x, clamped at x = 100, tip nodes at x = 120 (N, mm, t, s)
*NODE, NSET=NALL
1, 100., -5., -5.
2, 110., -5., -5.
3, 110., 5., -5.
4, 100., 5., -5.
5, 100., -5., 5.
6, 110., -5., 5.
7, 110., 5., 5.
8, 100., 5., 5.
9, 120., -5., -5.
10, 120., 5., -5.
11, 120., -5., 5.
12, 120., 5., 5.
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
2, 2, 9, 10, 3, 6, 11, 12, 7
*NSET, NSET=ROOT
1, 4, 5, 8
*NSET, NSET=TIP
9, 10, 11, 12
*NSET, NSET=TIPSIDE
9, 10, 11, 12, 6
*MATERIAL, NAME=STEEL
*ELASTIC
{E}, 0.3
*DENSITY
7.85e-9
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*BOUNDARY
ROOT, 1, 3
"""

with open(os.path.join(WORK, "brick.inp"), "w") as f:
    f.write(BRICK.replace("{E}", "210000."))
with open(os.path.join(WORK, "brick-soft.inp"), "w") as f:
    f.write(BRICK.replace("{E}", "70000."))

BASE = {
    "description": "base of the walk",
    "component": {
        "name": "brick",
        "source": {"calculix_deck": "brick.inp"},
        "boundary": {"node_set": "TIP"},
        "units": "N, mm, t, s",
        "rotation_axis": [0, 0, 1],
        "mass": "consistent",
    },
    "modal_campaign": {"methods": ["cb"], "modes": [2, 4], "frequencies": 4},
    # The oval closes first at mod(Omega t + phi, pi) = pi/2, a quarter of a
    # revolution: 0.3 revolution sees contact, friction and sliding.
    "rubbing": {
        "contact_nodes": [9, 10, 11, 12],
        "gap": {"oval": {"g_m": 0.01, "width": 0.15}},
        "friction_coefficient": 0.1,
        "rotation_speed": 1344.0,
        "tip_sliding": "with_rotation",
        "revolutions": 0.3,
        "steps_per_revolution": 1000,
        "output_every": 1,
        "response": {"node": 9, "direction": 2},
        "step_safety": 0.9,
        "campaign": {"runs": [{"method": "cb", "modes": [2]}], "full_revolutions": 0.3},
    },
    "damping": {"rayleigh": {"alpha": 10.0, "beta": 1e-7}, "modal_ratio": 0.01, "note": "base"},
}

# What each command's output is made of, without what varies from run to
# run (timings, memory): JSON keys and CSV columns naming seconds or memory.
TIMING = re.compile(r"(second|_s$|^us_per|memory|elapsed|wall)")


def normalized(path):
    name = os.path.basename(path)
    with open(path, "rb") as f:
        data = f.read()
    if name.endswith(".json"):
        def strip(x):
            if isinstance(x, dict):
                return {k: strip(v) for k, v in x.items() if not TIMING.search(k)}
            if isinstance(x, list):
                return [strip(v) for v in x]
            return x
        return json.dumps(strip(json.loads(data)), sort_keys=True).encode()
    if name.endswith(".csv"):
        rows = list(csv.reader(io.StringIO(data.decode())))
        if not rows:
            return b""
        keep = [j for j, c in enumerate(rows[0]) if not TIMING.search(c)]
        return "\n".join(",".join(r[j] for j in keep if j < len(r)) for r in rows).encode()
    if name.endswith(".md") or name.endswith(".png"):
        return b""
    return data


def fingerprint(out_dir, status, stderr, first_stdout_line):
    h = hashlib.sha256()
    h.update(("exit %d\n" % status).encode())
    # The message, not the progress lines (they count seconds).
    message = "\n".join(l for l in stderr.splitlines() if l.startswith("rsi: "))
    h.update(message.replace(WORK, "WORK").encode())
    h.update(first_stdout_line.replace(WORK, "WORK").encode())
    if os.path.isdir(out_dir):
        for root, _, files in sorted(os.walk(out_dir)):
            for name in sorted(files):
                path = os.path.join(root, name)
                h.update(os.path.relpath(path, out_dir).encode())
                h.update(normalized(path))
    return h.hexdigest()[:16]


# Command sets: what a key feeds.
COMMANDS = {
    "modes": [["modes", "--count", "4"]],
    "export": [["export"]],
    "full": [["simulate", "--method", "full"]],
    "cb": [["simulate", "--method", "cb", "--modes", "2"]],
    "rubbing": [["simulate", "--method", "full"], ["simulate", "--method", "cb", "--modes", "2"]],
    "campaign": [["campaign", "--no-report"]],
    "modal": [["modal-campaign", "--no-report"]],
    "sweep": [["sweep", "--no-report", "--quiet"]],
}

counter = [0]


def run(case, commands, extra_files=None):
    """The fingerprints of `commands` on `case` (a dict), one per command."""
    counter[0] += 1
    # One path for every case: the outputs (summaries) name the case file.
    path = os.path.join(WORK, "case.json")
    with open(path, "w") as f:
        json.dump(case, f)
    prints = []
    for k, command in enumerate(COMMANDS[commands]):
        out = os.path.join(WORK, "out-%d" % k)  # the same path for every case: messages name it
        p = subprocess.run([RSI] + command[:1] + [path] + command[1:] +
                           ["--ccx-cache", CACHE, "--out", out],
                           capture_output=True, text=True)
        first = p.stdout.splitlines()[0] if p.stdout and command[0] == "modes" else ""
        prints.append((p.returncode, fingerprint(out, p.returncode, p.stderr.replace(path, "CASE"),
                                                 first.replace(path, "CASE")),
                       p.stderr.strip().splitlines()[-1][:160] if p.stderr.strip() else ""))
        shutil.rmtree(out, ignore_errors=True)
    return prints


def setting(case, key, value):
    *parents, leaf = key.split(".")
    node = case
    for parent in parents:
        node = node.setdefault(parent, {})
    node[leaf] = value


def removing(case, key):
    *parents, leaf = key.split(".")
    node = case
    for parent in parents:
        node = node[parent]
    del node[leaf]


# The gmsh blade: its own base (data/cases/blade3d.json), keys through export.
BLADE = json.load(open(os.path.join(SRC, "data/cases/blade3d.json")))
BLADE.pop("modal_campaign", None)

# key -> (base, commands, [variants]); a variant is a function of a copy of
# the base. Every key of the README table needs an entry.
def with_value(key, value):
    return lambda c: setting(c, key, value)


def replace_source(source, boundary=None):
    def change(c):
        c["component"]["source"] = source
        if boundary is not None:
            c["component"]["boundary"] = boundary
    return change


def brick_matrices(c):
    c["component"]["source"] = {"calculix_deck": "brick.inp",
                                "calculix_matrices": os.path.join(WORK, "soft", "job")}


def constant_gap(c):
    c["rubbing"]["gap"] = {"constant": -0.002}


# The brick's rubbing run over two speeds (rsi sweep on a component case).
SWEEP_BASE = copy.deepcopy(BASE)
SWEEP_BASE["sweep"] = {"speeds": [1000, 1344], "revolutions": 0.3, "transient_revolutions": 0.1,
                       "runs": [{"method": "cb", "modes": [2]}]}

# The same with rotation effects: K(Omega) fitted at the default speeds
# (0.1 .. 1 x 1344 rad/s); the variant fits at other speeds.
SWEEP_ROTATING = copy.deepcopy(SWEEP_BASE)
SWEEP_ROTATING["component"]["rotation_effects"] = True

# The brick's rubbing run with rotation effects (the clearance at rest);
# the variant sets the clearance at a speed.
ROTATING_BASE = copy.deepcopy(BASE)
ROTATING_BASE["component"]["rotation_effects"] = True

# An abradable liner on the brick (lumped mass: the liner's node-by-node
# solve refuses a consistent one); the brick's run with it is refused all
# the same (EXEMPT below), so only adding the key is walked.
LINER_BASE = copy.deepcopy(BASE)
LINER_BASE["component"]["mass"] = "lumped"
LINER_BASE["rubbing"]["liner"] = {"thickness": 0.5, "young_modulus": 1000.0, "yield_stress": 1.0,
                                  "hardening_modulus": 100.0, "cells_around": 50}

WALK = {
    "component.name": (BASE, "export", [with_value("component.name", "block")]),
    "component.source.calculix_deck": (BASE, "modes", [with_value("component.source.calculix_deck", "brick-soft.inp")]),
    "component.source.calculix_matrices": (BASE, "modes", [brick_matrices]),
    "component.source.matrix_market": (BASE, "modes", [replace_source({"matrix_market": "mm-soft"}, {"nodes": [9, 10, 11, 12]})]),
    "component.boundary.nodes": (BASE, "cb", [with_value("component.boundary", {"nodes": [12, 11, 10, 9]})]),
    "component.boundary.node_set": (BASE, "cb", [with_value("component.boundary", {"node_set": "TIPSIDE"})]),
    "component.boundary": (BASE, "cb", [lambda c: removing(c, "component.boundary")]),
    "component.units": (BASE, "modes", [with_value("component.units", "N, mm, t, ms")]),
    "component.rotation_axis": (BASE, "rubbing", [with_value("component.rotation_axis", [0, 0.6, 0.8])]),
    "component.mass": (BASE, "modes", [with_value("component.mass", "lumped")]),
    "component.rotation_effects": (BASE, "rubbing", [with_value("component.rotation_effects", True)]),
    "rubbing.clearance_speed": (ROTATING_BASE, "rubbing", [with_value("rubbing.clearance_speed", 500.0)]),
    "modal_campaign.methods": (BASE, "modal", [with_value("modal_campaign.methods", ["cb", "macneal"])]),
    "modal_campaign.modes": (BASE, "modal", [with_value("modal_campaign.modes", [3])]),
    "modal_campaign.frequencies": (BASE, "modal", [with_value("modal_campaign.frequencies", 2)]),
    "rubbing": (BASE, "rubbing", [lambda c: removing(c, "rubbing")]),
    "rubbing.contact_nodes": (BASE, "rubbing", [with_value("rubbing.contact_nodes", [9, 10])]),
    "rubbing.gap.oval": (BASE, "rubbing", [with_value("rubbing.gap.oval.g_m", 0.02),
                                           with_value("rubbing.gap.oval.width", 0.3)]),
    "rubbing.gap.constant": (BASE, "rubbing", [constant_gap]),
    "rubbing.friction_coefficient": (BASE, "rubbing", [with_value("rubbing.friction_coefficient", 0.3)]),
    "rubbing.rotation_speed": (BASE, "rubbing", [with_value("rubbing.rotation_speed", -1344.0)]),
    "rubbing.tip_sliding": (BASE, "rubbing", [with_value("rubbing.tip_sliding", "against_rotation")]),
    "rubbing.revolutions": (BASE, "rubbing", [with_value("rubbing.revolutions", 0.31)]),
    "rubbing.steps_per_revolution": (BASE, "rubbing", [with_value("rubbing.steps_per_revolution", 900)]),
    "rubbing.output_every": (BASE, "rubbing", [with_value("rubbing.output_every", 3)]),
    "rubbing.response.node": (BASE, "rubbing", [with_value("rubbing.response.node", 10)]),
    "rubbing.response.direction": (BASE, "rubbing", [with_value("rubbing.response.direction", 1)]),
    "rubbing.step_safety": (BASE, "rubbing", [with_value("rubbing.step_safety", 0.3)]),
    "rubbing.liner": (BASE, "full", [with_value("rubbing.liner", LINER_BASE["rubbing"]["liner"])]),
    "rubbing.campaign.runs": (BASE, "campaign", [with_value("rubbing.campaign.runs", [{"method": "macneal", "modes": [2]}]),
                                                 with_value("rubbing.campaign.runs", [{"method": "cb", "modes": [3]}]),
                                                 with_value("rubbing.campaign.runs", [{"method": "cc", "modes": [1], "fixed_interface_modes": 2}])]),
    "rubbing.campaign.full_revolutions": (BASE, "campaign", [with_value("rubbing.campaign.full_revolutions", 0.28)]),
    "sweep": (SWEEP_BASE, "sweep", [lambda c: removing(c, "sweep")]),
    "sweep.speeds": (SWEEP_BASE, "sweep", [with_value("sweep.speeds", [1000, 1200]),
                                           with_value("sweep.speeds", {"from": 900, "to": 1300, "count": 3})]),
    "sweep.revolutions": (SWEEP_BASE, "sweep", [with_value("sweep.revolutions", 0.25)]),
    "sweep.transient_revolutions": (SWEEP_BASE, "sweep", [with_value("sweep.transient_revolutions", 0.15)]),
    "sweep.rotation_fit_speeds": (SWEEP_ROTATING, "sweep",
                                  [with_value("sweep.rotation_fit_speeds", [200, 400, 800, 1200, 1344, 2000])]),
    "sweep.runs": (SWEEP_BASE, "sweep", [with_value("sweep.runs", [{"method": "macneal", "modes": [2]}]),
                                         with_value("sweep.runs", [{"method": "full"}])]),
    "damping": (BASE, "rubbing", [lambda c: removing(c, "damping")]),
    "damping.rayleigh.alpha": (BASE, "full", [with_value("damping.rayleigh.alpha", 100.0)]),
    "damping.rayleigh.beta": (BASE, "full", [with_value("damping.rayleigh.beta", 1e-6)]),
    "damping.modal_ratio": (BASE, "cb", [with_value("damping.modal_ratio", 0.05)]),
    "damping.projected_rayleigh": (BASE, "full", [with_value("damping.projected_rayleigh", True)]),
}
# Free text: read, checked as strings, and on purpose without effect.
EXEMPT = {"description": "free text", "damping.note": "free text", "sweep.note": "free text"}
# The liner's own keys are not walked yet: the brick's liner run is refused
# (attach_liner finds a contact node's normal and tangential rows coupled in
# W with the lumped mass: the node-by-node solve needs W = c I on each node),
# so every variant gives that one message. Not free text: a known gap (a
# base model the liner accepts is needed here).
for _k in ("thickness", "young_modulus", "yield_stress", "hardening_modulus", "cells_around",
           "rows", "z_min", "z_max", "tip_patch"):
    EXEMPT["rubbing.liner." + _k] = "not walked yet: the brick's liner run is refused (its W is not c I per node)"
GMSH_KEYS = ["span", "chord", "thickness", "camber", "twist_deg", "stagger_deg", "root_length",
             "root_width", "root_height", "root_radius", "element_size", "young_modulus",
             "poisson_ratio", "density"]
GMSH_VALUES = {"span": 90.0, "chord": 38.0, "thickness": 3.5, "camber": 0.08, "twist_deg": 20.0,
               "stagger_deg": 35.0, "root_length": 52.0, "root_width": 13.0, "root_height": 18.0,
               "root_radius": 140.0, "element_size": 12.0, "young_modulus": 200000.0,
               "poisson_ratio": 0.25, "density": 8.0e-9}
for key in GMSH_KEYS:
    full = "component.source.gmsh_blade." + key
    WALK[full] = (BLADE, "export", [with_value(full, GMSH_VALUES[key])])
WALK["component.source.gmsh_blade"] = (BLADE, "export", [replace_source({"calculix_deck": os.path.join(WORK, "brick.inp")})])
# The bladed disk: the CI model made smaller still (3 sectors, element size
# 40 mm: each variant meshes and runs ccx again).
DISK = json.load(open(os.path.join(SRC, "data/cases/bladed-disk3d-ci.json")))
DISK["component"]["source"]["gmsh_bladed_disk"]["sectors"] = 3
DISK["component"]["source"]["gmsh_bladed_disk"]["blade"]["element_size"] = 40.0
DISK_VALUES = {"sectors": 4, "bore_radius": 100.0, "rim_radius": 165.0, "disk_width": 40.0,
               "blade": {"element_size": 35.0}}
for key, value in DISK_VALUES.items():
    full = "component.source.gmsh_bladed_disk." + key
    WALK[full] = (DISK, "export", [with_value(full, value)])
WALK["component.source.gmsh_bladed_disk"] = (DISK, "export", [replace_source({"calculix_deck": os.path.join(WORK, "brick.inp")}, {"node_set": "TIP"})])
# One's own sector deck (calculix_sector): one C3D8 brick, a quarter of a
# ring (inner radius 10 mm clamped, outer 20 mm; faces LEFT at 0 and RIGHT
# at 90 degrees), four of them a ring; FACE0 and FACE90 are the same faces
# by other names for the left and right variants (the pairing then fails:
# the message changes).
SECTOR_DECK = """** a quarter ring of one C3D8 brick (N, mm, t, s)
*NODE, NSET=NALL
1, 10., 0., 0.
2, 20., 0., 0.
3, 0., 20., 0.
4, 0., 10., 0.
5, 10., 0., 5.
6, 20., 0., 5.
7, 0., 20., 5.
8, 0., 10., 5.
*ELEMENT, TYPE=C3D8, ELSET=EALL
1, 1, 2, 3, 4, 5, 6, 7, 8
*NSET, NSET=HUB
1, 4, 5, 8
*NSET, NSET=LEFT
1, 2, 5, 6
*NSET, NSET=RIGHT
4, 3, 8, 7
*NSET, NSET=FACE0
2, 6
*NSET, NSET=FACE90
3, 7
*NSET, NSET=TIP
3, 7
*MATERIAL, NAME=STEEL
*ELASTIC
{E}, 0.3
*DENSITY
7.85e-9
*SOLID SECTION, ELSET=EALL, MATERIAL=STEEL
*BOUNDARY
HUB, 1, 3
"""
for name, modulus in (("sector.inp", "210000."), ("sector-soft.inp", "70000.")):
    with open(os.path.join(WORK, name), "w") as f:
        f.write(SECTOR_DECK.replace("{E}", modulus))
SECTOR = copy.deepcopy(BASE)
SECTOR["component"]["source"] = {"calculix_sector": {"deck": "sector.inp", "sectors": 4,
                                                     "left": "LEFT", "right": "RIGHT"}}
SECTOR["component"]["boundary"] = {"node_set": "TIP"}
for _k in ("modal_campaign", "rubbing", "damping"):
    SECTOR.pop(_k)
SECTOR_VALUES = {"deck": "sector-soft.inp", "sectors": 5, "left": "FACE90", "right": "FACE0"}
for key, value in SECTOR_VALUES.items():
    full = "component.source.calculix_sector." + key
    WALK[full] = (SECTOR, "export", [with_value(full, value)])
WALK["component.source.calculix_sector"] = (SECTOR, "export", [replace_source({"calculix_deck": os.path.join(WORK, "brick.inp")}, {"node_set": "TIP"})])
# The casing: the CI ring made coarser (element size 30 mm).
CASING = json.load(open(os.path.join(SRC, "data/cases/casing3d-ci.json")))
CASING["component"]["source"]["gmsh_casing"]["element_size"] = 30.0
CASING_VALUES = {"inner_radius": 280.0, "thickness": 6.0, "width": 50.0, "element_size": 25.0,
                 "clamped_flanges": 2, "young_modulus": 200000.0, "poisson_ratio": 0.25,
                 "density": 8.0e-9}
for key, value in CASING_VALUES.items():
    full = "component.source.gmsh_casing." + key
    WALK[full] = (CASING, "export", [with_value(full, value)])
WALK["component.source.gmsh_casing"] = (CASING, "export", [replace_source({"calculix_deck": os.path.join(WORK, "brick.inp")}, {"node_set": "TIP"})])
# The flexible casing of a rubbing case: the 3D system's CI case over 0.0005
# revolution (240 steps), the full run (casing.modes: a CB-2 run's).
SYSTEM = json.load(open(os.path.join(SRC, "data/cases/bladed-disk3d-casing-ci.json")))
SYSTEM["rubbing"]["revolutions"] = 0.0005
del SYSTEM["rubbing"]["campaign"]  # its full run's window is the case's 0.05 revolution
WALK["rubbing.casing"] = (SYSTEM, "full", [with_value("rubbing.casing.gmsh_casing.inner_radius", 270.55)])
WALK["rubbing.casing.gmsh_casing"] = (SYSTEM, "full", [with_value("rubbing.casing.gmsh_casing.thickness", 6.0)])
WALK["rubbing.casing.surface"] = (SYSTEM, "full", [with_value("rubbing.casing.surface", "SOUTER")])
WALK["rubbing.casing.modes"] = (SYSTEM, "cb", [with_value("rubbing.casing.modes", 12)])
WALK["rubbing.casing.forcing"] = (SYSTEM, "full", [with_value("rubbing.casing.forcing.pressure", 40.0),
                                                   with_value("rubbing.casing.forcing.nodal_diameters", 3),
                                                   with_value("rubbing.casing.forcing.duration", 1e-6)])


def documented_keys():
    """Every key in the first column of data/README.md's component table."""
    text = open(os.path.join(SRC, "data/README.md")).read()
    section = text[text.index("## Component case files"):]
    section = section[:section.index("\n## ", 10)] if "\n## " in section[10:] else section
    keys = []
    for line in section.splitlines():
        if not line.startswith("| `"):
            continue
        first = line.split("|")[1]
        names = re.findall(r"`([^`]+)`", first)
        for k, name in enumerate(names):
            if name.startswith(".") and k > 0:  # "`rubbing.response.node`, `.direction`"
                name = names[0].rsplit(".", 1)[0] + name
            keys.append(name)
    return keys


BASE_NAMES = {id(BASE): "brick", id(BLADE): "blade", id(SWEEP_BASE): "sweep",
              id(SWEEP_ROTATING): "sweep-rotating", id(ROTATING_BASE): "rotating",
              id(DISK): "disk", id(SECTOR): "sector", id(CASING): "casing", id(SYSTEM): "system"}


def main():
    failures = 0
    # The inputs the variants name: the soft brick's matrices and folder.
    soft = dict(copy.deepcopy(BASE))
    soft["component"]["source"] = {"calculix_deck": "brick-soft.inp"}
    path = os.path.join(WORK, "soft.json")
    json.dump(soft, open(path, "w"))
    subprocess.run([RSI, "export", path, "--ccx-cache", CACHE, "--out", os.path.join(WORK, "mm-export")],
                   check=True, capture_output=True)
    shutil.copytree(os.path.join(WORK, "mm-export", "brick"), os.path.join(WORK, "mm-soft"))
    entries = [e for e in os.listdir(CACHE) if e.startswith("brick-soft-") and e.endswith("-matrices")]
    os.makedirs(os.path.join(WORK, "soft"), exist_ok=True)
    for ext in ("sti", "mas", "dof"):
        shutil.copy(os.path.join(CACHE, entries[0], "job." + ext), os.path.join(WORK, "soft", "job." + ext))

    documented = documented_keys()
    missing = [k for k in documented if k not in WALK and k not in EXEMPT]
    for k in missing:
        print("FAIL %s: documented in data/README.md, but the walk has no variant for it" % k)
    failures += len(missing)
    for k, why in EXEMPT.items():
        print("exempt %s: %s" % (k, why))

    bases = {}
    order = [k for k in documented if k in WALK] + [k for k in WALK if k not in documented]
    for key in order:
        base, commands, variants = WALK[key]
        # Each base by itself: a variant of the disk compared with the
        # brick's output would change it whatever the key did.
        tag = (BASE_NAMES[id(base)], commands)
        if tag not in bases:
            first = run(copy.deepcopy(base), commands)
            again = run(copy.deepcopy(base), commands)
            if first != again:
                print("FAIL base %s %s is not deterministic: %s against %s" % (tag + (first, again)))
                failures += 1
            for status, _, message in first:
                if status != 0:
                    print("FAIL base %s %s: exit %d: %s" % (tag + (status, message)))
                    failures += 1
            bases[tag] = first
        for k, variant in enumerate(variants):
            case = copy.deepcopy(base)
            variant(case)
            got = run(case, commands)
            changed = got != bases[tag]
            outcome = "; ".join("exit %d %s%s" % (s, f, (" (" + m + ")") if s != 0 else "")
                                for s, f, m in got)
            print("%s %s [%d, %s]: %s" % ("ok  " if changed else "FAIL", key, k, commands,
                                          ("changes the output: " if changed else
                                           "changes nothing (read and ignored): ") + outcome))
            failures += 0 if changed else 1
    print("%d keys documented, %d walked (%d of them documented), %d exempt; %d failed" %
          (len(documented), len(order), len([k for k in documented if k in WALK]), len(EXEMPT),
           failures))
    sys.exit(1 if failures else 0)


main()
