"""The docs as the release ships them: each Markdown page rendered to one HTML page by Python-Markdown
(pinned in requirements.txt, so the same page gives the same bytes), links between pages pointing at the
rendered pages, headings with the anchors the pages link to."""
import html
import re

import markdown
from markdown.extensions import Extension
from markdown.extensions.toc import TocExtension
from markdown.treeprocessors import Treeprocessor

_PAGE_LINK = re.compile(r"^(?![a-z][a-z0-9+.-]*:)([^#]*)\.md(#.*)?$", re.IGNORECASE)
_STYLE = ("body{font-family:sans-serif;max-width:60em;margin:auto;padding:1em;line-height:1.4}"
          "table{border-collapse:collapse}td,th{border:1px solid #bbb;padding:.2em .5em;vertical-align:top}"
          "pre{background:#f4f4f4;padding:.5em;overflow-x:auto}code{background:#f4f4f4}")


class _LinksToHtml(Treeprocessor):
    """A link to another page (x.md, x.md#part) goes to its rendered page (x.html, x.html#part)."""

    def run(self, root):
        for a in root.iter("a"):
            href = a.get("href", "")
            m = _PAGE_LINK.match(href)
            if m:
                a.set("href", m.group(1) + ".html" + (m.group(2) or ""))


class _Links(Extension):
    def extendMarkdown(self, md):
        md.treeprocessors.register(_LinksToHtml(md), "pac_links_to_html", 5)


def _slug(value, separator):
    """GitHub's anchors, which the pages link to: lower case, punctuation dropped, a space a '-'."""
    value = re.sub(r"[^\w\- ]", "", value.strip().lower())
    return value.replace(" ", separator)


def render_page(text):
    """One Markdown page as a standalone HTML page."""
    md = markdown.Markdown(extensions=["tables", "fenced_code", "sane_lists", _Links(),
                                       TocExtension(slugify=_slug)])
    body = md.convert(text)
    title = next((line[2:].strip() for line in text.splitlines() if line.startswith("# ")), "PA-CONTROL")
    title = re.sub(r"[`*]", "", title)
    return (f'<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n<title>{html.escape(title)}</title>\n'
            f"<style>{_STYLE}</style>\n</head>\n<body>\n{body}\n</body>\n</html>\n")
