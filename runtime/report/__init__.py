"""The report's missing sections 6-8 (docs/sections.md): written from the studies' records.

:mod:`.sections` loads the records and renders the page through the Jinja2 template
``templates/sections.md.j2``; :mod:`.facts` holds every number, claim and table the page reads,
each a function of the records. Above ``studies`` and ``control`` (it reads both records), below
``cli`` (``slipmaps report``, runtime/cli/report.py).
"""
