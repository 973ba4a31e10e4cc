"""``tf`` for scripts that rosx runs: tf's old API over rosx's tf2 (`rosx.tf.tf1`), and
``tf.transformations`` (`rosx.tf.transformations`).

``tf.msg`` and ``tf.srv`` (``tfMessage``, ``FrameGraph``) come from the type store, like every
package's. A Python that cannot import rosx gets the next ``tf`` on its path instead.
"""

from __future__ import annotations

try:
    from rosx.client.modules import install as _install
    from rosx.tf.exceptions import (
        ConnectivityException,
        ExtrapolationException,
        LookupException,
    )
    from rosx.tf.exceptions import TransformException as Exception
    from rosx.tf.tf1 import TransformBroadcaster, Transformer, TransformerROS, TransformListener
except ImportError:
    from _rosx_shim import load_next  # type: ignore[import-not-found]

    load_next("tf")
else:
    _install()
    from tf import broadcaster, listener, transformations  # type: ignore[import-not-found]

    __all__ = [
        "ConnectivityException",
        "Exception",
        "ExtrapolationException",
        "LookupException",
        "TransformBroadcaster",
        "TransformListener",
        "Transformer",
        "TransformerROS",
        "broadcaster",
        "listener",
        "transformations",
    ]
