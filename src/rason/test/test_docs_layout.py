"""The repository's documentation layout: a short README as the landing page, a README in
every package (its ROS API: test_ros_api.py), and the site's link checker (tools/check_site_links.py)."""
import importlib.util
import os

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), '..', '..', '..'))
README_MAX_LINES = 150


def _packages():
    src = os.path.join(ROOT, 'src')
    return sorted(name for name in os.listdir(src)
                  if os.path.isfile(os.path.join(src, name, 'package.xml')))


def _link_checker():
    path = os.path.join(ROOT, 'tools', 'check_site_links.py')
    spec = importlib.util.spec_from_file_location('check_site_links', path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_readme_is_a_landing_page():
    with open(os.path.join(ROOT, 'README.md'), encoding='utf-8') as f:
        lines = f.read().splitlines()
    assert len(lines) <= README_MAX_LINES, \
        'README.md has %d lines; move details to docs/ (at most %d)' % (len(lines), README_MAX_LINES)


def test_every_package_has_a_readme():
    packages = _packages()
    assert 'rason_bridge' in packages and len(packages) >= 10, packages
    missing = [p for p in packages if not os.path.isfile(os.path.join(ROOT, 'src', p, 'README.md'))]
    assert not missing, 'packages without a README.md: %s' % ', '.join(missing)


def _write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, 'w', encoding='utf-8') as f:
        f.write(text)


def test_link_checker_finds_missing_pages_and_anchors(tmp_path):
    site = str(tmp_path)
    _write(os.path.join(site, 'index.html'),
           '<a href="guides/a.html#here">ok</a><a href="guides/a.html#gone">anchor</a>'
           '<a href="missing.html">page</a><a href="https://example.org/x">external</a>'
           '<img src="img/p.png">')
    _write(os.path.join(site, 'guides', 'a.html'), '<h2 id="here">Here</h2><a href="#here">self</a>'
           '<a href="#nowhere">self, broken</a><a href="../index.html">up</a>')
    _write(os.path.join(site, '404.html'), '<a href="/not/checked.html">root-relative</a>')
    broken = _link_checker().broken_links(site)
    found = sorted((os.path.relpath(page, site), link, why) for page, link, why in broken)
    assert found == [
        (os.path.join('guides', 'a.html'), '#nowhere', 'no such anchor'),
        ('index.html', 'guides/a.html#gone', 'no such anchor'),
        ('index.html', 'img/p.png', 'no such file'),
        ('index.html', 'missing.html', 'no such file'),
    ]


def test_link_checker_passes_a_whole_site(tmp_path):
    site = str(tmp_path)
    _write(os.path.join(site, 'index.html'), '<a href="b.html#x">b</a><a href="sub/">sub</a>')
    _write(os.path.join(site, 'b.html'), '<p id="x">x</p>')
    _write(os.path.join(site, 'sub', 'index.html'), '<a href="../b.html">b</a>')
    assert _link_checker().broken_links(site) == []


def _internal_actions():
    """The concrete internal actions of jason_lib's package rason: classes that extend Jason's
    DefaultInternalAction, directly or through the package's own abstract ones."""
    import re
    folder = os.path.join(ROOT, 'jason_lib', 'src', 'main', 'java', 'rason')
    parents, abstract = {}, set()
    for name in os.listdir(folder):
        if name.endswith('.java'):
            with open(os.path.join(folder, name), encoding='utf-8') as f:
                for modifiers, cls, parent in re.findall(r'^((?:public |abstract |final )*)class (\w+) extends ([\w.]+)',
                                                         f.read(), re.M):
                    parents[cls] = parent.split('.')[-1]
                    if 'abstract' in modifiers:
                        abstract.add(cls)

    def is_action(cls):
        while cls in parents:
            cls = parents[cls]
            if cls == 'DefaultInternalAction':
                return True
        return False
    return sorted(c for c in parents if is_action(c) and c not in abstract)


def test_the_internal_actions_page_lists_every_internal_action_rason_adds():
    import re
    actions = _internal_actions()
    assert {'time_ms', 'perceive_only'} <= set(actions), actions
    with open(os.path.join(ROOT, 'docs', 'reference', 'internal-actions.md'), encoding='utf-8') as f:
        listed = set(re.findall(r'`rason\.([a-z]\w*)', f.read()))
    assert listed == set(actions), 'docs/reference/internal-actions.md lists %s, jason_lib has %s' % (
        sorted(listed), actions)


def test_the_messages_page_includes_every_message_and_service_file():
    folder = os.path.join(ROOT, 'src', 'rason_msgs')
    files = ['src/rason_msgs/%s/%s' % (kind, name) for kind in ('msg', 'srv')
             for name in sorted(os.listdir(os.path.join(folder, kind)))]
    assert len(files) >= 10, files
    with open(os.path.join(ROOT, 'docs', 'reference', 'messages.md'), encoding='utf-8') as f:
        page = f.read()
    with open(os.path.join(folder, 'README.md'), encoding='utf-8') as f:
        readme = f.read()
    assert [p for p in files if '--8<-- "%s"' % p not in page] == [], 'not included in docs/reference/messages.md'
    assert [p for p in files if p.split('/', 2)[2] not in readme] == [], 'not in src/rason_msgs/README.md'
