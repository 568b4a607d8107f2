# fgc simulator run-time (fgc_sim_runtime.py): copied verbatim into every emitted simulator
"""The fgc simulator's run-time: data file, problem set-up, linearisation and cost.

A problem module (``<name>_sim.py``) holds the structure: variable and block tables, the block
kernels, each variable type's retraction and local coordinates, and the elimination schedule.
This module reads the data (measurements, noise, initial values) and evaluates all instances of
a block type at once, in the chosen float dtype.

The data file's format words are fgc's (``fgc.ir.datafile.MAGIC`` and ``ROBUST_CODES``); the
emitter refuses to emit a simulator whose run-time disagrees with them.
"""

import numpy

DATA_MAGIC = "FGCDATA 2"
NOISE_KINDS = ("isotropic", "diagonal", "full")  # the problem module's noise kind codes
ROBUST_NONE, ROBUST_HUBER, ROBUST_CAUCHY = 0, 1, 2
ALL = slice(None)  # every instance of a block


class SimDataError(Exception):
    """The data file does not fit the compiled problem. ``line`` is 1-based (0: whole file);
    ``factor`` / ``variable`` index the factor instance or variable concerned, if any."""

    def __init__(self, message, line=0, factor=None, variable=None):
        super().__init__(message)
        self.line, self.factor, self.variable = line, factor, variable


def read_data(path, structure=None):
    """The data file's variable and factor rows (float64 arrays) and their line numbers. With
    ``structure`` (the compiled structure fingerprint), a file of another structure is refused:
    equal counts do not mean equal factor connectivity."""
    try:
        with open(path, encoding="ascii") as handle:
            lines = handle.read().splitlines()
    except OSError as exc:
        raise SimDataError(f"{path}: cannot read data file ({exc.strerror})") from None
    except UnicodeDecodeError as exc:
        line = _line_of(path, exc.start)
        raise SimDataError(f"{path}:{line}: not an fgc data file (byte {exc.start} is not "
                           "ASCII)", line) from None
    first = lines[0].split() if lines else []
    if first[:2] != DATA_MAGIC.split():
        raise SimDataError(f"{path}:1: not an fgc data file (expected '{DATA_MAGIC} "
                           "<fingerprint>')", 1)
    if len(first) != 3:
        raise SimDataError(f"{path}:1: expected '{DATA_MAGIC}' and a structure fingerprint", 1)
    if structure is not None and first[2] != structure:
        raise SimDataError(f"{path}:1: the data file is for another structure: structure "
                           f"fingerprint {first[2]!r}, this simulator was compiled for "
                           f"{structure!r} (same counts do not mean the same factor "
                           "connectivity)", 1)
    header, sections = 1, []
    for name in ("VARIABLES", "FACTORS"):
        fields = lines[header].split() if header < len(lines) else []
        if len(fields) != 2 or fields[0] != name or not fields[1].isdigit():
            raise SimDataError(f"{path}:{header + 1}: expected '{name} <count>'", header + 1)
        first, count = header + 1, int(fields[1])
        what = "variable" if name == "VARIABLES" else "factor"
        sections.append([(_row(path, lines, first + i, what, i), first + i + 1)
                         for i in range(count)])
        header = first + count
    return sections[0], sections[1]


def _line_of(path, offset):
    """The 1-based line of byte ``offset`` of the file at ``path``."""
    with open(path, "rb") as handle:
        return handle.read(offset).count(b"\n") + 1


def _row(path, lines, pos, what, index):
    where = {what: index}
    if pos >= len(lines):
        raise SimDataError(f"{path}:{pos + 1}: file ends early ({what} {index} missing)",
                           pos + 1, **where)
    fields = lines[pos].split()
    try:
        count = int(fields[0])
        values = numpy.array(fields[1:], dtype=numpy.float64)
    except (ValueError, IndexError):
        raise SimDataError(f"{path}:{pos + 1}: malformed numbers ({what} {index})", pos + 1,
                           **where) from None
    if len(values) != count:
        raise SimDataError(f"{path}:{pos + 1}: expected {count} numbers, found {len(values)} "
                           f"({what} {index})", pos + 1, **where)
    if not numpy.all(numpy.isfinite(values)):
        raise SimDataError(f"{path}:{pos + 1}: non-finite number ({what} {index})", pos + 1,
                           **where)
    return values


class Block:
    """All instances of one block type: gathered inputs, noise, and index tables."""

    def __init__(self, spec, number, rows, x_offset, t_offset, dtype):
        self.number, self.spec, self.n = number, spec, len(spec["instances"])
        self.m, self.d = spec["residual_dim"], sum(spec["variable_dims"])
        inst = numpy.array(spec["instances"], dtype=numpy.intp).reshape(self.n, -1)
        self.storage = numpy.concatenate(
            [x_offset[inst[:, k], None] + numpy.arange(s)
             for k, s in enumerate(spec["variable_storage"])], 1)
        self.columns = numpy.concatenate(
            [t_offset[inst[:, k], None] + numpy.arange(dim)
             for k, dim in enumerate(spec["variable_dims"])], 1)
        self._split(rows, dtype)
        self.perm = _output_permutation(spec["residual_dim"], spec["variable_dims"])

    def _split(self, rows, dtype):
        """Cut the factor rows (n × line length) into measurements, noise and robust data."""
        meas, self.noise, self.robust, pos = [], [], [], 0
        for number, (_, _, kind, n_params, n_meas, _) in enumerate(self.spec["members"]):
            meas.append(rows[:, pos:pos + n_meas])
            params = rows[:, pos + n_meas:pos + n_meas + n_params]
            code, k = rows[:, pos + n_meas + n_params], rows[:, pos + n_meas + n_params + 1]
            self._check_noise(number, NOISE_KINDS[kind], params, code, k)
            self.noise.append(_whitening(NOISE_KINDS[kind], params.astype(dtype)))
            self.robust.append(None if not numpy.any(code) else
                               (code.astype(numpy.intp), k.astype(dtype)))
            pos += n_meas + n_params + 2
        self.meas = numpy.concatenate(meas, 1).astype(dtype)
        self.params = rows[:, _param_columns(self.spec["members"])].astype(dtype)

    def _check_noise(self, member, kind, params, code, k):
        diag = params if kind != "full" else params[:, _triu_diagonal(params.shape[1])]
        bad = numpy.flatnonzero(~numpy.all(diag > 0, 1))
        if len(bad):
            raise SimDataError(f"block type {self.number} member {member}: noise parameters of "
                               f"instance {bad[0]} are not positive",
                               factor=self.spec["factor_ids"][bad[0]])
        bad = numpy.flatnonzero(~numpy.isin(code, (0, 1, 2)) | ((code != 0) & ~(k > 0)))
        if len(bad):
            raise SimDataError(f"block type {self.number} member {member}: robust loss of "
                               f"instance {bad[0]} is invalid",
                               factor=self.spec["factor_ids"][bad[0]])

    def linearize(self, x, sel=ALL):
        """Whitened, robust-reweighted [J | −r] of the instances ``sel`` (default: all):
        an array (instances, M, D + 1)."""
        inputs = numpy.concatenate([x[self.storage[sel]], self.meas[sel]], 1)
        out = self.spec["jacobian"](numpy.ascontiguousarray(inputs.T))
        ab = numpy.ascontiguousarray(out[self.perm].T).reshape(len(inputs), self.m, self.d + 1)
        ab[..., -1] *= -1
        members = zip(self.spec["members"], self.noise, self.robust, strict=True)
        for (first, last, *_), noise, robust in members:
            rows = ab[:, first:last]
            rows[...] = noise(rows, sel)
            if robust is not None:
                norm = numpy.sqrt(numpy.sum(rows[..., -1] ** 2, -1))
                weight = _robust_weight((robust[0][sel], robust[1][sel]), norm)
                rows *= numpy.sqrt(weight)[:, None, None]
        return ab

    def cost(self, x, sel=ALL):
        """Σ over the instances ``sel`` and members of ½‖W r‖², or ρ(‖W r‖) where robust."""
        inputs = numpy.concatenate([x[self.storage[sel]], self.meas[sel], self.params[sel]], 1)
        costs = self.spec["cost"](numpy.ascontiguousarray(inputs.T))
        total = costs.dtype.type(0)
        for half, robust in zip(costs, self.robust, strict=True):
            if robust is not None:
                half = _robust_loss((robust[0][sel], robust[1][sel]), half)
            total += numpy.sum(half)
        return total


def _output_permutation(m, dims):
    """Kernel output rows → (row i, column c) of [J | r], row-major, c = D for the residual."""
    d = sum(dims)
    perm = numpy.zeros((m, d + 1), dtype=numpy.intp)
    perm[:, d] = numpy.arange(m)
    start, col = m, 0
    for dim in dims:
        perm[:, col:col + dim] = start + numpy.arange(m * dim).reshape(m, dim)
        start, col = start + m * dim, col + dim
    return perm.reshape(-1)


def _param_columns(members):
    cols, pos = [], 0
    for _, _, _, n_params, n_meas, _ in members:
        cols += range(pos + n_meas, pos + n_meas + n_params)
        pos += n_meas + n_params + 2
    return numpy.array(cols, dtype=numpy.intp)


def _triu_diagonal(n_params):
    size = int(round((numpy.sqrt(8 * n_params + 1) - 1) / 2))
    rows, cols = numpy.triu_indices(size)
    return numpy.flatnonzero(rows == cols)


def _whitening(kind, params):
    """(rows, instances) ↦ W·rows for one member: params are 1/σ, 1/σᵢ or the upper triangle
    of R."""
    if kind != "full":
        return lambda rows, sel: rows * params[sel][:, :, None]
    size = len(_triu_diagonal(params.shape[1]))
    w = numpy.zeros((len(params), size, size), dtype=params.dtype)
    w[:, numpy.triu_indices(size)[0], numpy.triu_indices(size)[1]] = params
    return lambda rows, sel: w[sel] @ rows


def _robust_weight(robust, e):
    """GTSAM's mEstimator weights w(e) (rows are scaled by √w)."""
    code, k = robust
    with numpy.errstate(divide="ignore", invalid="ignore"):
        huber = numpy.where(e <= k, e.dtype.type(1), k / e)
        cauchy = k * k / (k * k + e * e)
    return numpy.where(code == ROBUST_HUBER, huber, numpy.where(code == ROBUST_CAUCHY, cauchy, 1))


def _robust_loss(robust, half):
    """ρ(e) with e = √(2·½‖W r‖²); plain ½e² where the code is 0."""
    code, k = robust
    e = numpy.sqrt(2 * half)
    huber = numpy.where(e <= k, half, k * e - 0.5 * k * k)
    cauchy = 0.5 * k * k * numpy.log1p(e * e / (k * k))
    return numpy.where(code == ROBUST_HUBER, huber,
                       numpy.where(code == ROBUST_CAUCHY, cauchy, half))
