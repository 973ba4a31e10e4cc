"""``python -m rosx_commands …`` is ``rosx …``.

Ctrl-C (or roslaunch's SIGINT) while the program is still importing ends it quietly with 130,
as after it has started; a node interrupted that early shows no traceback.
"""

import sys

try:
    from rosx_commands.main import run

    run()
except KeyboardInterrupt:
    sys.exit(130)
