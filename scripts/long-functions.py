#!/usr/bin/env python3
"""List C++ functions longer than a limit (issue 15: none over 100 lines outside sgp4.cpp).

A rough scanner, not a parser: strips comments and literals, treats namespace/class/struct/union/enum
bodies as transparent and counts every other outermost brace block whose head ends in ')' (with
optional qualifiers) as a function, from the line of its name to its closing brace.
usage: scripts/long-functions.py [--limit N] [paths...]   (default: src menus, limit 100)
"""
import re, sys, pathlib

def strip(text):
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i); j = n if j < 0 else j; out.append(' ' * (j - i)); i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2); j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == '_')) and \
                re.match(r'R"([^()\\ ]{0,16})\(', text[i:i + 20]):
            m = re.match(r'R"([^()\\ ]{0,16})\(', text[i:i + 20])
            close = text.find(')' + m.group(1) + '"', i)
            end = n if close < 0 else close + len(m.group(1)) + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:end])); i = end
        elif c == "'" and i > 0 and (text[i - 1].isalnum()) and i + 1 < n and text[i + 1].isalnum():
            out.append(c); i += 1  # a digit separator (47'000'000), not a character literal
        elif c in '"\'':
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == '\\' else 1
            out.append(c + ' ' * (j - i - 1) + c); i = j + 1
        else:
            out.append(c); i += 1
    return ''.join(out)

QUALIFIER = re.compile(r'(?:\bconst|\bnoexcept|\boverride|\bfinal|\bmutable)$')
TRAILING_RETURN = re.compile(r'->[\w:<>,*& ]+$')


def function_head(h):
    """Whether a block's head ends as a function's: ')' and then only qualifiers or a trailing return
    type (stripped one by one: a single regex over a long initializer backtracked for minutes)."""
    t = h.rstrip()
    while True:
        m = QUALIFIER.search(t) or (TRAILING_RETURN.search(t[-200:]) if '->' in t[-200:] else None)
        if not m:
            break
        t = t[:len(t) - (len(t[-200:]) - m.start()) if m.re is TRAILING_RETURN else m.start()].rstrip()
    return t.endswith(')')


def scan(path, limit):
    text = strip(path.read_text(errors='replace'))
    stack, found = [], []   # stack of (kind, start_line, name)
    head_start = 0
    for i, c in enumerate(text):
        if c == '{':
            head = text[head_start:i]
            h = ' '.join(head.split())
            in_func = any(k == 'f' for k, _, _ in stack)
            if in_func:
                kind = 'b'
            elif re.search(r'\b(namespace|class|struct|union|enum)\b[^()]*$', h) or h.endswith('extern "C"'):
                kind = 't'
            elif function_head(h) and not re.search(r'=\s*$', h):
                kind = 'f'
            else:
                kind = 'b'
            name = ''
            if kind == 'f':
                m = re.search(r'([~\w:]+(?:<[^()]*>)?)\s*\([^()]*(?:\([^()]*\)[^()]*)*\)[^()]*$', h)
                name = m.group(1) if m else h[-60:]
                # the line of the function's name
                pos = head_start + len(head) - len(head.lstrip())
                start = text.count('\n', 0, pos) + 1
            else:
                start = text.count('\n', 0, i) + 1
            stack.append((kind, start, name))
            head_start = i + 1
        elif c == '}':
            if stack:
                kind, start, name = stack.pop()
                if kind == 'f':
                    end = text.count('\n', 0, i) + 1
                    if end - start + 1 > limit:
                        found.append((end - start + 1, f'{path}:{start}', name))
            head_start = i + 1
        elif c == ';':
            head_start = i + 1
        elif c == ':' and not in_ctor_init(text, head_start, i):
            pass
    return found

def in_ctor_init(text, a, b):
    return True

def main():
    args = sys.argv[1:]
    limit = 100
    if args[:1] == ['--limit']:
        limit = int(args[1]); args = args[2:]
    roots = [pathlib.Path(a) for a in (args or ['src', 'menus'])]
    found = []
    for r in roots:
        files = [r] if r.is_file() else sorted(list(r.rglob('*.cpp')) + list(r.rglob('*.h')))
        for f in files:
            found += scan(f, limit)
    for n, where, name in sorted(found, reverse=True):
        print(f'{n:5d}  {where}  {name}')
    return 0

if __name__ == '__main__':
    sys.exit(main())
