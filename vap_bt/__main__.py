"""``python -m vap_bt``: the ``vap-bt`` command, for a checkout without the console script."""

from vap_bt.app.cli import main

raise SystemExit(main())
