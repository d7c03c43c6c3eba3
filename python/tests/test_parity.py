"""Every command-line option has its Python counterpart: the commands and
their flags are read from the program's own `--help` (the independent
route: what a user of the command line sees), and each is looked up in the
table below — a keyword argument of the command's function, a method or
attribute of its result, or what the function returns in place of a file
or `--json`. A flag the table does not know fails the test, so a new
option cannot land without its Python name (or a stated reason it has
none yet, in GAPS)."""

import inspect
import re

import delta_stability as ds

# command → its function in the package
FUNCTIONS = {
    "quartic": ds.quartic,
    "response": ds.response,
    "analyze": ds.analyze,
    "convert": ds.convert,
    "report": ds.report,
    "sweep": ds.sweep,
    "size-tail": ds.size_tail,
    "sensitivity": ds.sensitivity,
    "uncertainty": ds.uncertainty,
}

# what a function returns stands for the command's --json and output files
RETURNS = "returns"

# (command, flag) → the keyword argument of the command's function (a str),
# a ("Class", "attribute") of its result, or RETURNS
PARITY = {
    ("quartic", "json"): ("Quartic", "to_dict"),
    ("quartic", "state-space"): ("Quartic", "state_space"),
    ("quartic", "class"): "class_",
    ("analyze", "mach"): "mach",
    ("analyze", "cg"): "cg",
    ("analyze", "damping"): "damping",
    ("analyze", "aero"): "aero",
    ("analyze", "omega-bar"): "omega_bar",
    ("analyze", "frequency-method"): "frequency_method",
    ("analyze", "datcom"): "datcom",
    ("analyze", "class"): "class_",
    ("analyze", "json"): ("Analysis", "to_dict"),
    ("analyze", "state-space"): ("Analysis", "state_space"),
    ("analyze", "write-derivatives"): ("Analysis", "write_derivatives"),
    ("sweep", "mach"): "mach",
    ("sweep", "sweep"): "sweep",
    ("sweep", "cg"): "cg",
    ("sweep", "mu1"): "mu1",
    ("sweep", "ib"): "i_b",
    ("sweep", "altitude"): "altitude",
    ("sweep", "mass"): "mass",
    ("sweep", "iy"): "I_y",
    ("sweep", "derivatives"): "derivatives",
    ("sweep", "damping"): "damping",
    ("sweep", "aero"): "aero",
    ("sweep", "omega-bar"): "omega_bar",
    ("sweep", "frequency-method"): "frequency_method",
    ("sweep", "datcom"): "datcom",
    ("sweep", "output"): ("SweepResult", "to_pandas"),
    ("response", "input"): "input",
    ("response", "until"): "until",
    ("response", "steps"): "steps",
    ("response", "m0"): "m0",
    ("response", "w0"): "w0",
    ("response", "neglect-zq-zwdot"): "neglect_zq_zwdot",
    ("response", "neglect-u"): "neglect_u",
    ("response", "until-s"): "until_s",
    ("response", "elevator-deg"): "elevator_deg",
    ("response", "csv"): RETURNS,
    ("convert", "from"): "notation",
    ("convert", "to"): "to",
    ("convert", "json"): RETURNS,
    ("sensitivity", "json"): RETURNS,
    ("report", "out"): "out",
    ("size-tail", "mach"): "mach",
    ("size-tail", "surface"): "surface",
    ("size-tail", "max-area"): "max_area",
    ("size-tail", "damping"): "damping",
    ("size-tail", "aero"): "aero",
    ("size-tail", "omega-bar"): "omega_bar",
    ("size-tail", "frequency-method"): "frequency_method",
    ("size-tail", "datcom"): "datcom",
    ("size-tail", "json"): RETURNS,
    ("uncertainty", "mach"): "mach",
    ("uncertainty", "samples"): "samples",
    ("uncertainty", "seed"): "seed",
    ("uncertainty", "sobol"): "sobol",
    ("uncertainty", "sampling"): "sampling",
    ("uncertainty", "damping"): "damping",
    ("uncertainty", "aero"): "aero",
    ("uncertainty", "omega-bar"): "omega_bar",
    ("uncertainty", "frequency-method"): "frequency_method",
    ("uncertainty", "datcom"): "datcom",
    ("uncertainty", "json"): RETURNS,
    ("uncertainty", "output"): RETURNS,
}

# the options Python does not have yet, and why
GAPS = {
    ("response", "svg"): "the plot: the returned columns, drawn with matplotlib",
    **{
        ("report", flag): "report CONFIG (a design's report across Mach): the note's study only"
        for flag in ["mach", "class", "damping", "aero", "omega-bar", "datcom", "frequency-method"]
    },
}

CLASSES = {
    "Quartic": ds.Quartic,
    "Analysis": ds.Analysis,
    "SweepResult": ds.SweepResult,
}


def _commands(cli):
    text = cli.run("--help").stdout
    block = text.split("Commands:")[1].split("Options:")[0]
    names = re.findall(r"^  ([a-z][a-z-]*)\s", block, re.M)
    return [n for n in names if n != "help"]


def _flags(cli, command):
    text = cli.run(command, "--help").stdout
    # clap's option lines: two spaces, then "-x, " or four more, then the
    # flag (a description's lines are indented further)
    flags = re.findall(r"^  (?:-[a-zA-Z], |    )--([a-z0-9-]+)", text, re.M)
    return [f for f in flags if f not in ("help", "version")]


def test_every_command_has_its_function(cli):
    commands = _commands(cli)
    assert len(commands) >= 9, commands
    assert sorted(commands) == sorted(FUNCTIONS)


def test_every_option_has_its_python_name(cli):
    seen = set()
    for command, function in FUNCTIONS.items():
        parameters = inspect.signature(function).parameters
        for flag in _flags(cli, command):
            key = (command, flag)
            seen.add(key)
            if key in GAPS:
                continue
            assert key in PARITY, f"{command} --{flag} has no Python counterpart in the table"
            target = PARITY[key]
            if target == RETURNS:
                continue
            if isinstance(target, tuple):
                cls, attr = target
                assert attr in dir(CLASSES[cls]), f"{command} --{flag}: {cls}.{attr}"
            else:
                assert target in parameters, f"{command} --{flag}: {function.__name__}({target}=…)"
    # and the table names no option the command line no longer has
    assert set(PARITY) | set(GAPS) == seen, (set(PARITY) | set(GAPS)) - seen
