#!/usr/bin/python3
"""Runs scripts/count_option_definitions.py on a small planted tree: it must count each kind of
hand-written definition once (a CLI literal, a Python keyword with a default, a keyword popped from
kwargs, a ROS row and a ROS parameter constant), leave lifted rows uncounted, list a front end's own
rows and a Python function's data arguments apart (not in the total), and refuse a folder that is not
a checkout rather than print a total of 0."""
import os
import subprocess
import sys
import tempfile

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "count_option_definitions.py")

PLANTED = {
    "src/cli/cmd_x.cpp": 'desc.add_options()\n  ("map", po::value<std::string>(), "map")\n  ("output,o", po::value<std::string>(), "out");\n'
                         'add_option_rows(desc, door_option_rows());\n'
                         'path_row("out-json", "FILE", TextKind::kOutput, &Outputs::json, "rooms");\n'
                         'text_row<Request>("at", "X,Y", set_point, "a point", true);\n',
    "src/python/x_bindings.cpp": 'm.def("f", &f, py::arg("grid"), py::arg("resolution") = 0.05, py::arg("clip") = true);\n'
                                 'm.def("g", &g, py::arg(row.name.c_str()) = row.get(defaults));\n'
                                 'const double t = pop<double>(kwargs, "tau", 2.5);\n'
                                 'py::dict d(py::arg("not_a_keyword") = 1);\n',
    "ros/adapter.cpp": 'rows.push_back({"settle_after", 2.0});\nconstexpr const char* kLedgerParameter = "id_ledger";\n',
}


def run(*args):
    done = subprocess.run([sys.executable, SCRIPT, *args], capture_output=True, text=True)
    return done.returncode, done.stdout.splitlines(), done.stderr


def expect(condition, message):
    if not condition:
        print("FAILED: " + message)
        sys.exit(1)


def main():
    with tempfile.TemporaryDirectory() as root:
        code, lines, error = run(root)
        expect(code == 2 and lines == [] and "not a topocut checkout" in error, f"an empty folder is counted: {code} {lines} {error}")
        for path, text in PLANTED.items():
            os.makedirs(os.path.dirname(os.path.join(root, path)), exist_ok=True)
            with open(os.path.join(root, path), "w", encoding="utf-8") as out:
                out.write(text)
        code, lines, _ = run(root, "--list")
        expect(code == 0, f"exit {code}")
        expect(lines[0] == "cli: 2" and "  src/cli/cmd_x.cpp: map" in lines and "  src/cli/cmd_x.cpp: output" in lines, f"cli: {lines}")
        expect("python: 2" in lines and "  src/python/x_bindings.cpp: clip" in lines and "  src/python/x_bindings.cpp: tau" in lines,
               f"python: {lines}")
        expect("ros: 2" in lines and "total: 6" in lines, f"ros or total: {lines}")
        # Apart, after the total: the command's own rows, and the array's resolution (data, no option).
        rest = lines[lines.index("total: 6") + 1:]
        expect(rest[0] == "not counted, front-end rows: 2" and "  src/cli/cmd_x.cpp: out-json" in rest and
               "  src/cli/cmd_x.cpp: at" in rest, f"front-end rows: {rest}")
        expect("not counted, data: 1" in rest and rest[-1] == "  src/python/x_bindings.cpp: resolution", f"data: {rest}")
    print("count_option_definitions: ok")


if __name__ == "__main__":
    main()
