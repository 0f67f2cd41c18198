"""Mitsuba 3's `orthogonal` sampler on the integrands of
`lab/examples/orthogonal_vs_mitsuba.rs`: per-pixel RMSE over PATTERNS seeds.

    python3 -m venv venv && venv/bin/pip install mitsuba numpy
    venv/bin/python lab/examples/orthogonal_vs_mitsuba.py > mitsuba.csv

Each seed is one pixel: `sampler.seed(seed)`, then for each of the
sample_count samples four `next_2d()` draws (dimensions 0 to 7, in the
order a renderer asks for them) and `advance()`. Mitsuba rounds a count
that is not the square of a prime up to the next one (with a warning); the
`used` column says what it rendered. Output: CSV `requested,used,integrand,
rmse` on standard output, for the Rust example's `--mitsuba` option.
"""

import math
import sys

import mitsuba as mi
import numpy as np

mi.set_variant("scalar_rgb")
mi.set_log_level(mi.LogLevel.Error)  # the rounding warnings: the `used` column says it

PATTERNS = 1024
COUNTS = [9, 16, 25, 49, 64, 121, 169, 256, 289, 961, 1024]

ONE_D = math.sqrt(math.pi) * math.erf(1.0) / 2.0  # integral of exp(-4 (x - 1/2)^2)
PAIR = math.sqrt(math.pi) * math.erf(1.0) - (1.0 - math.exp(-1.0))  # of exp(-(a - b)^2)
INTEGRANDS = {
    "coupled-4d": (lambda x: np.exp(-((x[:, 0] - x[:, 2]) ** 2 + (x[:, 1] - x[:, 3]) ** 2)), PAIR**2),
    "product-6d": (lambda x: np.exp(-4.0 * ((x[:, :6] - 0.5) ** 2).sum(axis=1)), ONE_D**6),
    "product-8d": (lambda x: np.exp(-4.0 * ((x[:, :8] - 0.5) ** 2).sum(axis=1)), ONE_D**8),
}


def main():
    print("requested,used,integrand,rmse")
    for n in COUNTS:
        sampler = mi.load_dict({"type": "orthogonal", "sample_count": n})
        used = sampler.sample_count()
        errors = {name: [] for name in INTEGRANDS}
        points = np.empty((used, 8))
        for seed in range(PATTERNS):
            sampler.seed(seed)
            for i in range(used):
                for pair in range(4):
                    p = sampler.next_2d()
                    points[i, 2 * pair] = p[0]
                    points[i, 2 * pair + 1] = p[1]
                sampler.advance()
            for name, (f, exact) in INTEGRANDS.items():
                errors[name].append(f(points).mean() - exact)
        for name in INTEGRANDS:
            rmse = math.sqrt(np.mean(np.square(errors[name])))
            print(f"{n},{used},{name},{rmse:.6e}")
        sys.stdout.flush()


if __name__ == "__main__":
    main()
