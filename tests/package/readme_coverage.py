#!/usr/bin/python3
"""Every command in README.md is run by a test: each fenced block a reader could paste (```sh,
```bash, ```shell, ```console, ```python, or a fence with no language) follows a line
`<!-- readme-test: NAME -->`, the NAMEs are unique, and each one is a block that
tests/package/readme_commands.py has checks for and that a ctest runs (`--block NAME` in a CMake file,
or NAME in a `foreach(block ...)` whose test passes `--block ${block}`).
Exit 1 naming each block that breaks this, so that no block can be added untested. Also, since the
README is mostly links now: every relative link and picture in README.md and docs/*.md names a file
that exists, and every #anchor a heading of that file.

One block is exempt from readme_commands.py: `setup`, the two set-up commands of a fresh machine
(`bash .ci/setup.sh demo`, `bash .ci/setup.sh test`). They install packages as root and build the
whole project, so CI runs them itself: this checks that the block holds exactly those two commands
and that .ci/run runs both.

    readme_coverage.py SOURCE_DIR          check SOURCE_DIR/README.md
    readme_coverage.py --self-test         check that planted mistakes are caught
"""
import os
import re
import sys

RUNNABLE = {"", "sh", "bash", "shell", "console", "python", "python3", "py"}
SETUP = "setup"
SETUP_COMMANDS = ["bash .ci/setup.sh demo", "bash .ci/setup.sh test"]
CMAKE_FILES = ("CMakeLists.txt", "ros/CMakeLists.txt", "cmake/python.cmake")


def blocks(text):
    """(line number, language, marker name or None, body) of every fenced block in a Markdown text."""
    found = []
    lines = text.split("\n")
    k = 0
    while k < len(lines):
        fence = re.match(r"^(```+|~~~+)\s*([\w+-]*)", lines[k])
        if not fence:
            k += 1
            continue
        start, close = k, fence.group(1)
        end = next((j for j in range(k + 1, len(lines)) if lines[j].startswith(close)), len(lines))
        marker = re.fullmatch(r"<!-- readme-test: ([\w-]+) -->", lines[k - 1].strip()) if k else None
        found.append((start + 1, fence.group(2).lower(), marker.group(1) if marker else None,
                      "\n".join(lines[k + 1:end])))
        k = end + 1
    return found


def problems(readme, checked, registered, ci_run):
    """What breaks the rule in a README's text, given the blocks readme_commands.py checks, the blocks
    a ctest runs and the text of .ci/run."""
    wrong, seen = [], set()
    for line, language, name, body in blocks(readme):
        if language not in RUNNABLE:
            continue
        if name is None:
            wrong.append(f"README.md:{line}: a ```{language} block without <!-- readme-test: NAME --> before it: "
                         "no test runs it")
            continue
        if name in seen:
            wrong.append(f"README.md:{line}: a second block named {name}")
        seen.add(name)
        if name == SETUP:
            commands = [c.split("#")[0].strip() for c in body.split("\n") if c.split("#")[0].strip()]
            if commands != SETUP_COMMANDS:
                wrong.append(f"README.md:{line}: the setup block runs {commands}, not exactly {SETUP_COMMANDS} "
                             "(the only commands CI runs itself)")
            for command in SETUP_COMMANDS:
                mode = command.split()[-1]
                if not re.search(r'setup\.sh"? %s\b' % mode, ci_run):
                    wrong.append(f"README.md:{line}: .ci/run does not run `{command}`, so nothing runs it")
        elif name not in checked:
            wrong.append(f"README.md:{line}: tests/package/readme_commands.py has no checks for the block {name}")
        elif name not in registered:
            wrong.append(f"README.md:{line}: no ctest runs the block {name} (--block {name} in {', '.join(CMAKE_FILES)})")
    return wrong


def slug(heading):
    """The anchor GitHub gives a Markdown heading."""
    return re.sub(r"[^\w\- ]", "", heading.strip().lower()).replace(" ", "-")


def broken_links(source):
    """Relative links and pictures of README.md and docs/*.md that lead nowhere."""
    docs = os.path.join(source, "docs")
    files = ["README.md"] + sorted("docs/" + f for f in os.listdir(docs) if f.endswith(".md")) if os.path.isdir(docs) \
        else ["README.md"]
    anchors, texts = {}, {}
    for name in files:
        with open(os.path.join(source, name), encoding="utf-8") as f:
            texts[name] = f.read()
        outside = re.sub(r"^```.*?^```", "", texts[name], flags=re.S | re.M)
        anchors[os.path.normpath(name)] = {slug(h) for h in re.findall(r"^#+ (.*)$", outside, re.M)}
    wrong = []
    for name, text in texts.items():
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            if re.match(r"[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            resolved = os.path.normpath(os.path.join(os.path.dirname(name), path)) if path else os.path.normpath(name)
            if not os.path.exists(os.path.join(source, resolved)):
                wrong.append(f"{name}: the link {target} leads to no file")
            elif anchor and resolved in anchors and anchor not in anchors[resolved]:
                wrong.append(f"{name}: the link {target} names no heading of {resolved}")
    return wrong


def check(source):
    sys.path.insert(0, os.path.join(source, "tests", "package"))
    from readme_commands import CHECKS

    def read(name):
        path = os.path.join(source, name)
        return open(path, encoding="utf-8").read() if os.path.exists(path) else ""

    cmake = "".join(read(f) for f in CMAKE_FILES)
    registered = set(re.findall(r"--block ([\w-]+)", cmake))  # one test, or one per name of a foreach(block ...)
    for names in re.findall(r"foreach\(block ([^)]*)\)[^\n]*\n(?:(?!endforeach)[^\n]*\n)*?[^\n]*--block \$\{block\}", cmake):
        registered.update(names.split())
    wrong = problems(read("README.md"), set(CHECKS), registered, read(".ci/run")) + broken_links(source)
    for line in wrong:
        print("readme_coverage: " + line)
    if not wrong:
        named = [name for _, language, name, _ in blocks(read("README.md")) if language in RUNNABLE]
        print(f"readme_coverage: all {len(named)} runnable blocks of README.md are run: {', '.join(named)}")
    return 1 if wrong else 0


def self_test():
    """Each planted mistake is reported, and a README without one is not."""
    ci = 'bash "$here/setup.sh" test\nbash "$here/setup.sh" demo\n'
    good = ("<!-- readme-test: setup -->\n```sh\nbash .ci/setup.sh demo\nbash .ci/setup.sh test  # all\n```\n"
            "<!-- readme-test: a -->\n```sh\nbuild/topocut segment m.yaml\n```\n```yaml\nkey: 1\n```\n")
    planted = {
        "unmarked sh": good + "```sh\nrm -rf out\n```\n",
        "unmarked bash": good + "```bash\nls\n```\n",
        "unmarked python": good + "```python\nimport topocut\n```\n",
        "unmarked plain fence": good + "```\nbuild/topocut --help\n```\n",
        "marker not right before": good + "<!-- readme-test: a2 -->\n\n```sh\nls\n```\n",
        "unchecked name": good + "<!-- readme-test: nobody -->\n```sh\nls\n```\n",
        "unregistered name": good + "<!-- readme-test: b -->\n```sh\nls\n```\n",
        "name twice": good + "<!-- readme-test: a -->\n```sh\nls\n```\n",
        "setup runs more": good.replace("setup.sh test", "setup.sh test\nbuild/topocut lines scan.csv"),
    }
    failures = []
    if problems(good, {"a", "b", "nobody2"}, {"a"}, ci):
        failures.append("a README whose blocks are all run was refused: %s" % problems(good, {"a"}, {"a"}, ci))
    if not problems(good, {"a"}, {"a"}, 'bash "$here/setup.sh" test\n'):
        failures.append("a setup command .ci/run does not run was not reported")
    for what, text in planted.items():
        if not problems(text, {"a", "b"}, {"a", "nobody"}, ci):
            failures.append(f"not reported: {what}")
    for line in failures:
        print("readme_coverage --self-test: " + line)
    if not failures:
        print(f"readme_coverage --self-test: all {len(planted) + 1} planted mistakes reported")
    return 1 if failures else 0


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(self_test() if sys.argv[1] == "--self-test" else check(sys.argv[1]))
