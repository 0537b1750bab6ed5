#!/usr/bin/env python3
"""Elements per IFC type and storey, counted from the STEP text alone (independent of assimp
and IFC++): an element's storey is the IfcBuildingStorey reached through
IfcRelContainedInSpatialStructure and IfcRelAggregates. Gives the expected figures of
Mesh.*Storeys* in test_mesh.cpp.  Usage: ifc_storeys.py FILE.ifc"""
import collections
import re
import sys

TYPES = ('IFCWALL', 'IFCWALLSTANDARDCASE', 'IFCSLAB', 'IFCWINDOW', 'IFCDOOR')


def entities(text):
    text = re.sub(r'\r?\n', '', text)
    return {int(m.group(1)): (m.group(2), m.group(3))
            for m in re.finditer(r'#(\d+)\s*=\s*([A-Z0-9]+)\((.*?)\);', text)}


def links(ents):
    storeys, up = {}, {}
    for i, (t, a) in ents.items():
        if t == 'IFCBUILDINGSTOREY':
            storeys[i] = re.findall(r"'([^']*)'", a)[1]
        elif t == 'IFCRELCONTAINEDINSPATIALSTRUCTURE':
            m = re.search(r'\(([^()]*)\)\s*,\s*#(\d+)\s*$', a)
            for x in re.findall(r'#(\d+)', m.group(1)):
                up[int(x)] = int(m.group(2))
        elif t == 'IFCRELAGGREGATES':
            m = re.search(r'#(\d+)\s*,\s*\(([^()]*)\)\s*$', a)
            for x in re.findall(r'#(\d+)', m.group(2)):
                up.setdefault(int(x), int(m.group(1)))
    return storeys, up


def storey_of(i, storeys, up):
    for _ in range(8):
        if i in storeys:
            return storeys[i]
        if i not in up:
            return ''
        i = up[i]
    return ''


def main(path):
    ents = entities(open(path, encoding='latin-1').read())
    storeys, up = links(ents)
    counts = collections.Counter()
    for i, (t, _) in ents.items():
        if t in TYPES:
            counts[(t.replace('STANDARDCASE', ''), storey_of(i, storeys, up))] += 1
    for (t, s), n in sorted(counts.items()):
        print(f'{t:12s} {s:15s} {n}')


if __name__ == '__main__':
    main(sys.argv[1])
