"""Doxygen's input filter for the public headers (docs/Doxyfile.in): the headers document their
API in plain // comments, which Doxygen does not read, so this turns them into its own on the
fly, leaving the sources as they are. A file's opening comment becomes its \\file text, a comment
line before a declaration ///, a comment after one on its line ///<; characters Doxygen would take
as commands or HTML are escaped in them.

    python3 docs/doxygen_filter.py HEADER    # prints the filtered header
"""
import re
import sys

TRAILING = re.compile(r"^(.*?[;,{]\s*)//\s?(.*)$")
LEADING = re.compile(r"^(\s*)//\s?(.*)$")


def escape(text):
    """Escapes outside `code spans` (Doxygen's Markdown shows those as they are); a line with an
    odd number of backticks is escaped whole."""
    def plain(part):  # std::sin would be a link request Doxygen cannot resolve
        return special.sub(r"\\\1", part).replace("std::", "std\\::")

    special = re.compile(r"([\\@<>&#%$])")
    parts = text.split("`")
    if len(parts) % 2 == 0:
        return plain(text)
    return "`".join(plain(p) if k % 2 == 0 else p for k, p in enumerate(parts))


def main(path):
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    out = []
    opening = True
    for line in lines:
        if opening and LEADING.match(line) and not line.startswith(" "):
            if not out:
                out.append("/// \\file")
            out.append("/// " + escape(LEADING.match(line).group(2)))
            continue
        opening = False
        m = LEADING.match(line)
        if m:
            out.append(m.group(1) + "/// " + escape(m.group(2)))
            continue
        m = TRAILING.match(line)
        if m and '"' not in m.group(1):
            out.append(m.group(1) + "///< " + escape(m.group(2)))
            continue
        out.append(line)
    sys.stdout.write("\n".join(out))


if __name__ == "__main__":
    main(sys.argv[1])
