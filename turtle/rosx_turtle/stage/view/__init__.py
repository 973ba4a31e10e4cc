"""The simulator drawn in a terminal: `picture` (the world as pixels, numpy only), `widget`
(a textual widget showing them in half blocks), `app` (stageros's screen) and `run`."""
