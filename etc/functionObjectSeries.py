"""Function-object output read back as sphCastFoam's readFunctionObjectSeries reads it
(src/post/FunctionObject.h): the rows of every postProcessing/<name>/<startTime>/<file>, each
start folder's rows taken before the next folder's exact `# startTime`, so a restarted run's
series equals the uninterrupted one's. Shared by the tutorials' comparison scripts; standard
library only."""
import math
import os
import sys


def _read_file(path):
    """The exact start time (the header's `# startTime`), the '#' lines and the rows of one file;
    an unfinished last line (a killed run) is left out."""
    start, header, rows = None, [], []
    with open(path) as f:
        lines = f.read().split('\n')[:-1]   # the last piece has no newline: cut off, or empty
    for line in lines:
        if line.startswith('#'):
            header.append(line)
            if line.startswith('# startTime '):
                start = float(line.split()[2])
        elif line.strip():
            rows.append([float(w) for w in line.replace('(', ' ').replace(')', ' ').split()])
    return start, header, rows


def read_series(name, field):
    """(rows, header) of postProcessing/<name>/*/<field> in the current case: rows are the numbers
    of each line, time first (the brackets of vectors dropped); header the '#' lines of the first
    start folder. Exits with a message when the run wrote none."""
    folder = os.path.join('postProcessing', name)
    starts = sorted((float(d), d) for d in os.listdir(folder)
                    if os.path.isfile(os.path.join(folder, d, field))) \
        if os.path.isdir(folder) else []
    if not starts:
        sys.exit('no %s: run sphCastFoam first' % os.path.join(folder, '*', field))
    files = [_read_file(os.path.join(folder, d, field)) for _, d in starts]
    rows = []
    for k, (_, _, file_rows) in enumerate(files):
        cut = math.inf
        if k + 1 < len(files):
            cut = files[k + 1][0] if files[k + 1][0] is not None else starts[k + 1][0]
            cut -= 1e-10 * abs(cut)   # rows print 12 digits: one that close is that start
        rows += [r for r in file_rows if r[0] < cut]
    return rows, files[0][1]
