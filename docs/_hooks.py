"""mkdocs hook: moik's docstrings cite names as Sphinx roles (``:func:`moik.solve_ik```,
``:class:`~moik.problems.Target```); mkdocstrings renders them as a role prefix before
inline code. This drops the prefix (and Sphinx's ``~`` short-name marker), leaving the
code."""

import re

_ROLE = re.compile(r":(?:func|class|mod|meth|attr|data|exc|obj|py:\w+):(<code[^>]*>)~?")


def on_page_content(html, **kwargs):
    return _ROLE.sub(r"\1", html)
