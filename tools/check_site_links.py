#!/usr/bin/python3
"""Check every relative link of a built site: the file exists and so does its #anchor.

mkdocs 1.4 checks that linked pages exist but not their anchors; this closes the gap.
Usage: check_site_links.py SITE_DIR (exit status 1 and one line per broken link).
"""
import os
import sys
from html.parser import HTMLParser
from urllib.parse import unquote, urlsplit


class _Page(HTMLParser):
    def __init__(self):
        super().__init__()
        self.ids = set()
        self.links = []

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if attrs.get('id'):
            self.ids.add(attrs['id'])
        if tag == 'a' and attrs.get('name'):
            self.ids.add(attrs['name'])
        for key in ('href', 'src'):
            if attrs.get(key):
                self.links.append(attrs[key])


def _parse(path):
    page = _Page()
    with open(path, encoding='utf-8') as f:
        page.feed(f.read())
    return page


def broken_links(site):
    """(page, link, why) for every relative link of the site's HTML pages that leads nowhere."""
    pages = {}
    for folder, _, names in os.walk(site):
        for name in names:
            # 404.html links from the site's root, as a server would serve it.
            if name.endswith('.html') and name != '404.html':
                path = os.path.join(folder, name)
                pages[os.path.normpath(path)] = _parse(path)
    broken = []
    for path, page in sorted(pages.items()):
        for link in page.links:
            parts = urlsplit(link)
            if parts.scheme or parts.netloc or link.startswith('//'):
                continue
            target = os.path.normpath(os.path.join(os.path.dirname(path), unquote(parts.path))) \
                if parts.path else path
            if os.path.isdir(target):
                target = os.path.join(target, 'index.html')
            if not os.path.exists(target):
                broken.append((path, link, 'no such file'))
            elif parts.fragment and target in pages and unquote(parts.fragment) not in pages[target].ids:
                broken.append((path, link, 'no such anchor'))
    return broken


def main(argv):
    site = argv[1] if len(argv) > 1 else 'build/site'
    broken = broken_links(site)
    for path, link, why in broken:
        print('%s: %s: %s' % (os.path.relpath(path, site), link, why))
    print('links: %d broken in %s' % (len(broken), site))
    return 1 if broken else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
