from asterlite.cli import main

raise SystemExit(main())
