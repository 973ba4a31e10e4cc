"""map_server's maps: `files` (the YAML + image conventions, sans-I/O), `server`
(``map_server``) and `saver` (``map_saver``)."""
