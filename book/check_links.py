#!/usr/bin/env python3
"""Checks the links of the built book.

    python3 book/check_links.py book/book

Every local `href` and `src` of every HTML page must name a file of the
build, and where it has a #fragment that names an HTML page, an `id` (or
an anchor's `name`) in that page. External http(s) links are listed, not
fetched (CI has no general network). Exits 1 when a link is broken.
"""

import os
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlsplit

LINKING = {"href", "src"}


class Page(HTMLParser):
    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.ids = set()
        self.links = []
        self.base = None

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        for key in ("id",):
            if attrs.get(key):
                self.ids.add(attrs[key])
        if tag == "a" and attrs.get("name"):
            self.ids.add(attrs["name"])
        if tag == "base" and attrs.get("href"):
            self.base = attrs["href"]
            return
        for key in LINKING:
            value = attrs.get(key)
            if value is not None:
                self.links.append((tag, key, value.strip()))

    handle_startendtag = handle_starttag


def parse(path):
    page = Page()
    with open(path, encoding="utf-8", errors="replace") as f:
        page.feed(f.read())
    return page


def main():
    if len(sys.argv) != 2:
        print("usage: python3 book/check_links.py BUILT_BOOK", file=sys.stderr)
        return 2
    root = os.path.abspath(sys.argv[1])
    pages = {}
    for folder, _, files in os.walk(root):
        for f in files:
            if f.endswith(".html"):
                path = os.path.join(folder, f)
                pages[path] = parse(path)
    if not pages:
        print(f"check_links.py: no HTML pages under {root}", file=sys.stderr)
        return 1
    checked, broken, external = 0, [], set()
    for path, page in sorted(pages.items()):
        here = os.path.dirname(path)
        if page.base and page.base.startswith("/"):
            # mdBook's 404 page: its links are relative to the site's root.
            here = os.path.join(root, page.base.lstrip("/"))
        for tag, key, link in page.links:
            parts = urlsplit(link)
            if parts.scheme in ("http", "https") or link.startswith("//"):
                external.add(link)
                continue
            if parts.scheme in ("mailto", "javascript", "data", "tel"):
                continue
            if parts.scheme:
                broken.append((path, link, f"unknown scheme {parts.scheme}"))
                continue
            checked += 1
            if not parts.path:
                target = path
            elif parts.path.startswith("/"):
                target = os.path.join(root, unquote(parts.path).lstrip("/"))
            else:
                target = os.path.normpath(os.path.join(here, unquote(parts.path)))
            if os.path.isdir(target):
                target = os.path.join(target, "index.html")
            if not os.path.isfile(target):
                broken.append((path, link, "no such file"))
                continue
            fragment = unquote(parts.fragment)
            if fragment and target.endswith(".html"):
                ids = pages[target].ids if target in pages else parse(target).ids
                if fragment not in ids:
                    broken.append((path, link, f"no id '{fragment}' in {os.path.relpath(target, root)}"))
    for path, link, why in broken:
        print(f"broken: {os.path.relpath(path, root)}: {link}: {why}")
    if external:
        print(f"external links (listed, not fetched): {len(external)}")
        for link in sorted(external):
            print(f"  {link}")
    print(
        f"check_links.py: {len(pages)} pages, {checked} local links checked, "
        f"{len(broken)} broken, {len(external)} external listed"
    )
    return 1 if broken else 0


if __name__ == "__main__":
    sys.exit(main())
