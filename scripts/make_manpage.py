#!/usr/bin/python3
"""make_manpage.py: the man page swarf.1 from the program's own command-line help.

Usage: make_manpage.py SWARF OUT.1

Runs `SWARF --help`, `SWARF --version` and `SWARF SUB --help` for every subcommand the help lists
(and their subcommands, as `swarf case keys`), and writes a roff man page: NAME, SYNOPSIS,
DESCRIPTION, OPTIONS, one COMMANDS subsection per subcommand with its help as printed, FILES,
ENVIRONMENT, EXIT STATUS, SEE ALSO. The page holds no build date or path, so the same program
gives the same page. CMake runs it after building swarf (the target swarf_manpage) and installs
the page as share/man/man1/swarf.1.
"""
import os
import re
import subprocess
import sys


def run(args):
    r = subprocess.run(args, capture_output=True, text=True, timeout=60,
                       env=dict(os.environ, COLUMNS="100", OMP_NUM_THREADS="1"))
    if r.returncode != 0:
        sys.exit("make_manpage.py: %s exited %d: %s" % (" ".join(args), r.returncode, r.stderr.strip()))
    return r.stdout


def roff(text):
    """Text as roff: backslashes escaped, a leading '.' or "'" made literal, '-' as a hyphen-minus."""
    out = []
    for line in text.rstrip("\n").split("\n"):
        line = line.replace("\\", "\\e").replace("-", "\\-")
        if line.startswith(".") or line.startswith("'"):
            line = "\\&" + line
        out.append(line)
    return "\n".join(out)


def subcommands(help_text):
    """[(name, summary)] of the help's 'Subcommands:' section (CLI11's layout)."""
    subs, inside = [], False
    for line in help_text.split("\n"):
        if line.strip() == "Subcommands:":
            inside = True
            continue
        if inside:
            m = re.match(r"^  (\S+)\s+(.*)$", line)
            if m:
                subs.append((m.group(1), m.group(2).strip()))
            elif line.strip() and not line.startswith("   "):
                inside = False
    return subs


def strip_usage_path(text, exe):
    """'Usage: /some/build/bin/swarf run' -> 'Usage: swarf run' (no build path in the page)."""
    return text.replace(exe, "swarf")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: make_manpage.py SWARF OUT.1")
    exe, out = sys.argv[1], sys.argv[2]
    top = strip_usage_path(run([exe, "--help"]), exe)
    version = run([exe, "--version"]).split("\n")[0].strip()  # "swarf 0.1.0" (the rest names the build)
    summary = top.split("\n")[0].split(":", 1)[-1].strip()
    page = [
        '.TH SWARF 1 "" "%s" "User Commands"' % version,
        ".SH NAME",
        "swarf \\- %s" % roff(summary),
        ".SH SYNOPSIS",
        ".B swarf",
        "[\\fIOPTIONS\\fR] \\fISUBCOMMAND\\fR [\\fIARGS\\fR]",
        ".br",
        ".B swarf run",
        "[\\fICASE.toml\\fR] [\\fB\\-\\-out\\fR \\fIDIR\\fR] [\\fB\\-\\-set\\fR \\fItable.key=value\\fR]...",
        ".SH DESCRIPTION",
        "swarf simulates orthogonal metal cutting by the discrete element method: a workpiece of spheres on a",
        "face-centred cubic lattice bonded by elastic-plastic rods (linear kinematic hardening, viscous part,",
        "failure), cut by a rigid triangulated tool on a prescribed path, with Hertz contacts and friction,",
        "integrated by the implicit Newmark step or explicit Verlet. Every number a case sets or a run writes",
        "is in SI units unless its key or column says otherwise. Without a case file,",
        ".B swarf run",
        "runs the built-in default case, an orthogonal cut of C45 steel.",
        ".PP",
        "The subcommands and their options follow, as",
        ".B swarf SUBCOMMAND \\-\\-help",
        "prints them.",
        ".SH OPTIONS",
        ".nf",
        roff(top.split("Options:", 1)[1].split("Subcommands:", 1)[0].strip("\n")),
        ".fi",
        ".SH COMMANDS",
    ]
    for name, _ in subcommands(top):
        text = strip_usage_path(run([exe, name, "--help"]), exe)
        page += [".SS %s" % roff("swarf " + name), ".nf", roff(text), ".fi"]
        for sub, _ in subcommands(text):
            inner = strip_usage_path(run([exe, name, sub, "--help"]), exe)
            page += [".SS %s" % roff("swarf %s %s" % (name, sub)), ".nf", roff(inner), ".fi"]
    page += [
        ".SH FILES",
        ".TP",
        ".I share/swarf/postprocess",
        "the scripts a run calls for its plots and pictures, and the ParaView script's template",
        "(beside the program's prefix; SWARF_POSTPROCESS_DIR overrides it).",
        ".TP",
        ".I share/swarf/examples",
        "example cases: the default cut written out, the same cut in cutting terms ([cut]), a cut with heat.",
        ".TP",
        ".I share/doc/swarf",
        "the documentation: case-reference.md lists every case key with its unit, default and range;",
        "outputs.md every file a run writes.",
        ".SH ENVIRONMENT",
        ".TP",
        ".B OMP_NUM_THREADS",
        "threads when \\fB\\-\\-threads\\fR is not given.",
        ".TP",
        ".B SWARF_POSTPROCESS_DIR",
        "where the post-processing scripts are, instead of the installed ones.",
        ".SH EXIT STATUS",
        "0 on success; 2 for bad input (the message names the file, key and value) or a run refused before",
        "its first step; 3 for a run stopped because it blew up (the message says where and why); 130 and",
        "143 for a run interrupted by SIGINT or SIGTERM (after writing a checkpoint when checkpoints are on).",
        ".SH SEE ALSO",
        ".BR paraview (1),",
        ".BR mpirun (1)",
    ]
    text = "\n".join(page) + "\n"
    tmp = out + ".part"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, out)


if __name__ == "__main__":
    main()
