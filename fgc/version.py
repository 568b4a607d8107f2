"""fgc's version, in a module of its own so that the backends read it without importing the
whole package (fgc/__init__ imports the application)."""

__version__ = "0.1.0"
