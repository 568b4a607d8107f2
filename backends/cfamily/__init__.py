"""The C-family layer the ``hls`` and ``native`` backends share: the sympy → C++ printer and its
function wrappers (``printer``, ``special``), sanitised names (``names``), the data and index
tables (``tables``), block contexts and sparsity tiles (``blocks``, ``sparsity``), step patterns
(``steps``), retractions printed from fgc's geometry (``retract``) and the reading and judging of
results (``results``). It is not a backend; nothing here knows whether it prints hardware or a
CPU program."""
