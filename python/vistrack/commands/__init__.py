"""Sub-commands of the ``vistrack`` command line, one module each."""
