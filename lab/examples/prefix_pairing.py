"""The trade between prefixes and independence for a shuffle of a pixel's sample indices.

Run: python3 lab/examples/prefix_pairing.py   (numpy; seeded, under a minute on 2 cores)

Model: a 1D draw of a progressive sequence is an Owen-scrambled van der Corput stream (index i -> the
radical inverse of order[i], Owen-scrambled, jittered inside its 2^-M stratum), and two draws of one
pixel use independently keyed orders and scrambles. The orders permute each dyadic block [2^m, 2^(m+1))
of indices onto itself (so every power-of-two prefix keeps its set), in one of these ways:

- identity: the unshuffled order (each aligned block of 2^k indices is a stratified set);
- shell:    a uniform permutation of each block (what `prefix_shuffle` approximates);
- K<k>tree: the low k bits of the offset inside the block shuffled uniformly inside each aligned 2^k
            sub-block, the bits above under a nested (MSB-first tree) scramble, so every aligned
            sub-block of >= 2^k indices maps onto an aligned sub-block. K0tree is a full nested
            scramble of the offset;
- K<k>id:   the low k bits as in K<k>tree, the bits above unshuffled.

Printed, per order:
1. the independence ratio: mean |corr| over a pixel's n samples of two such draws, over that of two
   independently shuffled stratified sets (what `tests/pixel/independence.rs` measures), n = 4, 16, 64;
2. the RMSE of the 1D Gaussian integrand exp(-4 (x - 1/2)^2) over the first n = 12, 24, 48, 100 samples
   (of a 128-sample stream), as a ratio to the identity order's;
3. the Owen scramble of the index (Burley 2020) in both directions, over a whole prefix of 2^m:
   MSB-first (index bit j flipped by a function of the bits above j: Burley's reverse, Laine-Karras,
   reverse) and LSB-first (bit j flipped by a function of the bits below: an Owen scramble of the
   radical inverse of the index), with the fraction of pixels whose two draws' top bits are tied
   (equal for every sample, or opposite for every sample).
"""
import numpy as np

T = 20000  # pixels (pairs of draws) per cell
rng = np.random.default_rng(38)


def owen(v, m):
    """Nested uniform scramble (MSB-first tree) of m-bit ints, one independent tree per row of v."""
    out = np.zeros_like(v)
    rows = np.arange(v.shape[0])[:, None]
    for k in range(m):
        shift = m - 1 - k
        flips = rng.integers(0, 2, size=(v.shape[0], 1 << k))
        out |= (((v >> shift) & 1) ^ flips[rows, v >> (shift + 1)]) << shift
    return out


def reverse(v, m):
    r = np.zeros_like(v)
    for b in range(m):
        r |= ((v >> b) & 1) << (m - 1 - b)
    return r


def uniform_rows(rows, n):
    """rows independent uniform permutations of 0..n."""
    return np.argsort(rng.random((rows, n)), axis=1)


def order(n, K, high):
    """(T, n) indices: each dyadic block [lo, 2 lo) permuted onto itself."""
    p = np.tile(np.arange(n), (T, 1))
    lo = 1
    while lo < n:
        m = lo.bit_length() - 1
        offs = np.tile(np.arange(lo), (T, 1))
        if high != 'identity':
            k = m if K is None else min(K, m)
            hi, low = offs >> k, offs & ((1 << k) - 1)
            if m - k > 0 and high == 'tree':
                hi = owen(hi, m - k)
            perms = uniform_rows(T * (lo >> k), 1 << k).reshape(T, lo >> k, 1 << k)
            sub = offs >> k
            low = perms[np.arange(T)[:, None], sub, low]
            offs = hi << k | low
        p[:, lo:min(2 * lo, n)] = (lo + offs)[:, :min(lo, n - lo)]
        lo *= 2
    return p


def points(idx, m):
    return (owen(reverse(idx, m), m) + rng.random(idx.shape)) / (1 << m)


def abs_corr(a, b):
    a = a - a.mean(axis=1, keepdims=True)
    b = b - b.mean(axis=1, keepdims=True)
    return np.abs((a * b).sum(1) / np.sqrt((a * a).sum(1) * (b * b).sum(1))).mean()


def independence(n, make):
    m = n.bit_length() - 1
    return abs_corr(points(make(n), m), points(make(n), m))


def full(n):
    return uniform_rows(T, n)


ORDERS = [('shell', None, 'uniform')] + [
    (f'K{k}{h}', k, h) for k in range(4) for h in ('tree', 'id') if not (k == 0 and h == 'id')]

print('1. independence ratio (mean |corr| over independently shuffled stratified sets)')
print('| n | ' + ' | '.join(name for name, _, _ in ORDERS) + ' |')
for n in (4, 16, 64):
    ref = independence(n, full)
    cells = [independence(n, lambda n, K=K, h=h: order(n, K, h)) / ref for _, K, h in ORDERS]
    print(f'| {n} | ' + ' | '.join(f'{c:.3f}' for c in cells) + ' |', flush=True)

print('2. RMSE of exp(-4 (x - 1/2)^2) at prefix n, over the identity order\'s')
N, M = 128, 7
xs = (np.arange(1 << 20) + 0.5) / (1 << 20)
exact = np.exp(-4 * (xs - 0.5) ** 2).mean()


def rmse(idx, n):
    x = points(idx, M)[:, :n]
    return np.sqrt(((np.exp(-4 * (x - 0.5) ** 2).mean(1) - exact) ** 2).mean())


ident = order(N, None, 'identity')
print('| n | identity RMSE | ' + ' | '.join(name for name, _, _ in ORDERS) + ' |')
for n in (12, 24, 48, 100):
    base = rmse(ident, n)
    cells = [rmse(order(N, K, h), n) / base for _, K, h in ORDERS]
    print(f'| {n} | {base:.2e} | ' + ' | '.join(f'{c:.2f}' for c in cells) + ' |', flush=True)

print('3. an Owen scramble of the whole index, both directions')
print('| n | direction | ratio | ties | independent sets\' ties |')
for n in (4, 16, 64):
    m = n.bit_length() - 1
    base_idx = np.tile(np.arange(n), (T, 1))
    fa, fb = points(full(n), m), points(full(n), m)
    ref = abs_corr(fa, fb)
    def tied(a, b):
        same = (a >= 0.5) == (b >= 0.5)
        return (same.all(1) | (~same).all(1)).mean()
    for name, make in (('MSB-first (Burley)', lambda: owen(base_idx, m)),
                       ('LSB-first', lambda: reverse(owen(reverse(base_idx, m), m), m))):
        a, b = points(make(), m), points(make(), m)
        print(f'| {n} | {name} | {abs_corr(a, b) / ref:.3f} | {tied(a, b):.2f} | {tied(fa, fb):.2f} |',
              flush=True)
