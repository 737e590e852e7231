#!/usr/bin/env python3
# A transcription of protocol/codec/CODEC.md (codec version 7, the wake lattice of section 7.9 and its hulls' presence included) and of PROTOCOL.md 7.1 (frame
# records) into plain Python, written from the text alone (no FlatBuffers package: a few lines
# read the Welcome and SceneUpdate tables). It checks that the two documents suffice to decode:
# the function values of CODEC.md 12.1, the scene-model hashes of 12.2 and every chunk, refusal,
# state hash and frame of the stream vectors beside this file (12.3), bit for bit - the choppy
# channels of version 3, the binary32 synthesis of version 4, the float32 Jacobian and the
# cascaded streams of version 5 included (float32 emulated by struct, per operation).
# Informative; CTest runs it as codec_vectors_python when a Python 3 interpreter is found.
# Usage: decode_from_docs.py [--big]   (--big adds the 256 x 256 hash of 12.2, about a second)
import math, os, struct, sys, time

HERE = os.path.dirname(os.path.abspath(__file__))


M64 = 1 << 64
def wrap64(x):
    x &= M64 - 1
    return x - M64 if x >= 1 << 63 else x

kTwoPi = 6.283185307179586
kTwoPiLo = 2.4492935982947064e-16
kPi = 3.1415926535897931
kHalfPi = 1.5707963267948966
kHalfPiLo = 6.1232339957367660e-17
kLn2Hi = 0.69314718036912382
kLn2Lo = 1.9082149292705877e-10
kInvLn2 = 1.4426950408889634
kSqrtHalf = 0.70710678118654757
kHalfLog2Pi = 0.91893853320467278
B = [None, 0.083333333333333329, -0.0027777777777777779, 0.00079365079365079365, -0.00059523809523809529,
     0.00084175084175084171, -0.0019175269175269176, 0.0064102564102564100, -0.029550653594771242]
assert kPi == kTwoPi / 2 and kHalfPi == kTwoPi / 4
assert struct.unpack('<Q', struct.pack('<d', kLn2Hi))[0] == 0x3FE62E42FEE00000

# ---- 2. notation
def round_shift(p, s):
    return wrap64((p + (1 << (s - 1))) >> s)
def mul_sym(a, b, s):
    p = a * b
    if p >= 0:
        return wrap64((p + (1 << (s - 1))) >> s)
    return wrap64(-((-p + (1 << (s - 1))) >> s))
def to_fixed(x, q):
    return int(math.floor(math.ldexp(x, q) + 0.5))

# ---- 3.1
def reduce_(x):
    m = math.floor(x / kTwoPi + 0.5)
    return (x - m * kTwoPi) - m * kTwoPiLo
def det_cos(x):
    r = reduce_(x); r2 = r * r; acc = 1.0
    for j in range(28, 0, -1):
        acc = 1.0 - acc * r2 / float((2 * j - 1) * (2 * j))
    return acc
def det_sin(x):
    r = reduce_(x); r2 = r * r; acc = 1.0
    for j in range(28, 0, -1):
        acc = 1.0 - acc * r2 / float((2 * j) * (2 * j + 1))
    return r * acc
def det_exp_neg(y):
    if not (y >= 0): return 1.0
    if y > 745: return 0.0
    m = 0; z = y
    while z >= 0.5:
        z = z * 0.5; m += 1
    acc = 1.0
    for j in range(24, 0, -1):
        acc = 1.0 - acc * z / float(j)
    for _ in range(m):
        acc = acc * acc
    return acc
def det_tanh(x):
    if not (x > 0): return 0.0
    if x > 20: return 1.0
    e = det_exp_neg(2 * x)
    return (1 - e) / (1 + e)
def det_w(k, g, D):
    if not (k > 0): return 0.0
    t = det_tanh(k * D) if D > 0 else 1.0
    return math.sqrt(g * k * t)

# ---- 3.2
def det_wrap_angle(x):
    r = math.fmod(x, kTwoPi)
    if r > kPi: r = r - kTwoPi
    elif r < -kPi: r = r + kTwoPi
    return r
def det_log(x):
    if x != x or x < 0: return float('nan')
    if x == 0: return float('-inf')
    if x == float('inf'): return x
    m, e = math.frexp(x)
    if m < kSqrtHalf:
        m = m * 2; e = e - 1
    f = m - 1; s = f / (m + 1); s2 = s * s
    acc = 0.0
    for j in range(12, 0, -1):
        acc = 1 / float(2 * j + 1) + s2 * acc
    t = s + s
    lm = t + t * (s2 * acc)
    return float(e) * kLn2Hi + (lm + float(e) * kLn2Lo)
def det_exp(x):
    if x != x: return x
    if x > 710: return float('inf')
    if x < -746: return 0.0
    k = math.floor(x * kInvLn2 + 0.5)
    r = (x - k * kLn2Hi) - k * kLn2Lo
    acc = 1.0
    for j in range(16, 0, -1):
        acc = 1 + acc * r / float(j)
    k = int(k)
    # ldexp with one rounding
    if k < -1000:
        return math.ldexp(math.ldexp(acc, k + 64), -64)
    try:
        if k > 1023:
            return math.ldexp(acc * 2, k - 1)
        return math.ldexp(acc, k)
    except OverflowError:  # IEEE gives +inf; Python raises
        return float('inf')
def det_pow(x, y):
    return det_exp(y * det_log(x))
def det_atan2(y, x):
    if x != x or y != y: return float('nan')
    ax = abs(x); ay = abs(y)
    if ax == 0 and ay == 0: return 0.0
    swap = ay > ax
    a = ax / ay if swap else ay / ax
    for _ in range(2):
        a = a / (1 + math.sqrt(1 + a * a))
    a2 = a * a
    acc = 0.0
    for j in range(12, 0, -1):
        acc = 1 / float(2 * j + 1) - a2 * acc
    angle = 4 * (a - a * (a2 * acc))
    if swap: angle = kHalfPi - angle
    if x < 0: angle = kPi - angle
    return -angle if y < 0 else angle
def det_log_gamma(x):
    if x != x or x <= 0: return float('nan')
    if x == float('inf'): return x
    z = x; p = 1.0
    while z < 16:
        p = p * z; z = z + 1
    inv = 1 / z; inv2 = inv * inv
    series = 0.0
    for j in range(8, 0, -1):
        series = B[j] + inv2 * series
    lg = (((z - 0.5) * det_log(z) - z) + kHalfLog2Pi) + inv * series
    return lg - det_log(p)
def det_cosh(x):
    e = det_exp(abs(x))
    return (e + 1 / e) * 0.5

# ---- 4. FFTs: radix-2 stages after a bit reversal; rows, then columns
class Radix2:
    def __init__(self, n):
        self.n = n; self.bits = n.bit_length() - 1
    def one(self, re, im, inverse):
        n = self.n
        for i in range(n):
            j = int(format(i, '0%db' % self.bits)[::-1], 2) if self.bits else 0
            if j > i:
                re[i], re[j] = re[j], re[i]; im[i], im[j] = im[j], im[i]
        length = 2
        while length <= n:
            half = length // 2; stride = n // length
            for start in range(0, n, length):
                for j in range(half):
                    self.butterfly(re, im, start + j, start + j + half, j, stride, length, inverse)
            length *= 2
    def two(self, re, im, inverse=True):  # re, im: lists of rows
        n = self.n
        for r in range(n):
            self.one(re[r], im[r], inverse)
        for c in range(n):
            cr = [re[r][c] for r in range(n)]; ci = [im[r][c] for r in range(n)]
            self.one(cr, ci, inverse)
            for r in range(n):
                re[r][c] = cr[r]; im[r][c] = ci[r]

# ---- 4.1 fixed point
class FFT(Radix2):
    def __init__(self, n):
        super().__init__(n)
        self.C = []; self.S = []
        for j in range(n // 2):
            angle = (kTwoPi * j) / n
            self.C.append(to_fixed(det_cos(angle), 30)); self.S.append(to_fixed(det_sin(angle), 30))
    def butterfly(self, re, im, a, b, j, stride, length, inverse):
        wr = self.C[j * stride]; wi = self.S[j * stride] if inverse else -self.S[j * stride]
        tr = round_shift(re[b] * wr - im[b] * wi, 30)
        ti = round_shift(re[b] * wi + im[b] * wr, 30)
        re[b] = wrap64(re[a] - tr); im[b] = wrap64(im[a] - ti)
        re[a] = wrap64(re[a] + tr); im[a] = wrap64(im[a] + ti)

# ---- 4.2 binary32 inverse FFT (synthesis): each operation rounded to float32 (f32v)
class FloatFFT(Radix2):
    def __init__(self, n):
        super().__init__(n)
        self.C = [f32v(det_cos((kTwoPi * j) / n)) for j in range(n // 2)]
        self.S = [f32v(det_sin((kTwoPi * j) / n)) for j in range(n // 2)]
    def butterfly(self, re, im, a, b, j, stride, length, inverse):
        if j == 0: wr, wi = 1.0, 0.0
        elif 4 * j == length: wr, wi = 0.0, 1.0
        else: wr = self.C[j * stride]; wi = self.S[j * stride]
        tr = f32v(f32v(re[b] * wr) - f32v(im[b] * wi))
        ti = f32v(f32v(re[b] * wi) + f32v(im[b] * wr))
        re[b] = f32v(re[a] - tr); im[b] = f32v(im[a] - ti)
        re[a] = f32v(re[a] + tr); im[a] = f32v(im[a] + ti)

# ---- 5. payload
def crc16(data, crc=0xFFFF):
    for b in data:
        crc ^= b << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021) & 0xFFFF if crc & 0x8000 else (crc << 1) & 0xFFFF
    return crc
assert crc16(b'123456789') == 0x29B1

class Refused(Exception):
    pass

def varint32(p, pos):
    v = 0
    for i in range(5):
        if pos >= len(p): raise Refused('truncated')
        b = p[pos]; pos += 1
        v |= (b & 0x7F) << (7 * i)
        if not b & 0x80:
            if v >= 1 << 32: raise Refused('bad_range')
            return v, pos
    raise Refused('bad_range')

def parse_payload(env, p, max_payload, grid_log2):
    tick, baseline, key, index, count = env
    if len(p) > max_payload: raise Refused('oversized')
    if len(p) < 4: raise Refused('truncated')
    flags = p[0]
    if not flags & 0x20: raise Refused('unknown_version')  # bit 5: binary32 synthesis, version 4
    h = dict(key=bool(flags & 1), normals=bool(flags & 2), modeled=bool(flags & 4), whole=bool(flags & 8),
             choppy=bool(flags & 16), cascaded=bool(flags & 64), wake=bool(flags & 128), tag=p[3])
    if h['key'] != key or (h['modeled'] and not h['key']): raise Refused('bad_flags')
    pos = 4
    if not h['whole']:
        h['begin'], pos = varint32(p, pos)
        h['end'], pos = varint32(p, pos)
    if h['key'] and not h['modeled']:
        if pos + 2 > len(p): raise Refused('truncated')
        h['pos_shift'] = p[pos]; h['vel_shift'] = p[pos + 1]; pos += 2
    pseudo = struct.pack('<QQBHHB', tick, baseline, 1 if key else 0, index, count, grid_log2)
    if crc16(pseudo + bytes(p[0:1]) + bytes(p[3:])) != (p[1] | p[2] << 8): raise Refused('checksum_mismatch')
    h['body'] = bytes(p[pos:])
    return h

# ---- 6. range decoder and body
class RangeDecoder:
    def __init__(self, body):
        self.b = body; self.pos = 0; self.range = 0xFFFFFFFF; self.code = 0
        for _ in range(4):
            self.code = ((self.code << 8) | self.next()) & 0xFFFFFFFF
    def next(self):
        v = self.b[self.pos] if self.pos < len(self.b) else 0
        self.pos += 1
        return v
    def normalize(self):
        while self.range < 1 << 24:
            self.range = (self.range << 8) & 0xFFFFFFFF
            self.code = ((self.code << 8) | self.next()) & 0xFFFFFFFF
    def bit(self, model, i):
        p = model[i]
        bound = (self.range >> 11) * p
        if self.code < bound:
            self.range = bound; model[i] = p + ((2048 - p) >> 5); bit = 0
        else:
            self.code -= bound; self.range -= bound; model[i] = p - (p >> 5); bit = 1
        self.normalize()
        return bit
    def direct(self):
        self.range >>= 1
        if self.code >= self.range:
            self.code -= self.range; bit = 1
        else:
            bit = 0
        self.normalize()
        return bit

class UInt:
    def __init__(self):
        self.length = [1024] * 41; self.mant = [[1024] * 3 for _ in range(41)]
    def decode(self, rc):
        nb = 0
        while rc.bit(self.length, nb) == 1:
            nb += 1
            if nb >= 40: raise Refused('bad_value')
        x = 1
        if nb >= 1:
            first = rc.bit(self.mant[nb], 0); x = x << 1 | first
            if nb >= 2:
                second = rc.bit(self.mant[nb], 1 + first); x = x << 1 | second
                for _ in range(nb - 2):
                    x = x << 1 | rc.direct()
        return x - 1

class SInt:
    def __init__(self):
        self.zs = [1024, 1024]; self.mag = UInt()  # zs[0] zero model, zs[1] sign model
    def nonzero(self, rc):
        neg = rc.bit(self.zs, 1)
        m = self.mag.decode(rc) + 1
        return -m if neg else m
    def decode(self, rc):
        if rc.bit(self.zs, 0) == 0: return 0
        return self.nonzero(rc)

def ctx(a, b):
    return min(31, (abs(a) + abs(b)).bit_length())

# Correction channels in coding order: 0 height, 1 slope_x, 2 slope_z, 3 disp_x, 4 disp_z, 5 disp_xx,
# 6 disp_zz, 7 disp_xz.
def channels_of(normals, choppy):
    return [0] + ([1, 2] if normals else []) + ([3, 4, 5, 6, 7] if choppy else [])

def decode_body(S, samples, normals, choppy, begin, end, body):
    rc = RangeDecoder(body)
    X = [SInt() for _ in range(32)]; V = [SInt() for _ in range(32)]
    count = UInt(); gap = UInt(); value = [SInt() for _ in range(8)]
    key = []
    pr = pi = 0
    for i in range(begin, min(end, S)):
        c = ctx(pr, pi)
        xr = X[c].decode(rc); xi = X[c].decode(rc)
        c2 = ctx(xr, xi)
        vr = V[c2].decode(rc); vi = V[c2].decode(rc)
        key.append((xr, xi, vr, vi)); pr, pi = xr, xi
    corr = [[] for _ in range(8)]
    if end > S:
        rb = max(begin, S) - S; re_ = end - S
        for ch in channels_of(normals, choppy):
            n = count.decode(rc)
            if n > re_ - rb: raise Refused('bad_value')
            prev = rb - 1
            for _ in range(n):
                g = gap.decode(rc)
                pos = prev + 1 + g
                if pos >= re_: raise Refused('bad_value')
                v = value[ch].nonzero(rc)
                if abs(v) > 1 << 24: raise Refused('bad_value')
                corr[ch].append((pos, v)); prev = pos
    return key, corr

# ---- 7. modal model
def s_(i, n):
    return i if i < n // 2 else i - n

class Stream:
    def __init__(self, grid, patch_x, patch_z, gravity, R, hstep, sstep, normals, dstep=None, choppy=False):
        self.n = n = grid; self.L = n.bit_length() - 1; self.hc = n // 2 + 1
        self.samples = n * n; self.modes = n * self.hc; self.cascaded = False
        self.patch_x, self.patch_z, self.g, self.R = patch_x, patch_z, gravity, R
        self.hstep, self.sstep, self.normals = hstep, sstep, normals
        self.dstep, self.choppy = dstep, choppy
        self.G = {}  # choppiness -> [G_0 .. G_4] (7.1)
        self.fft = FFT(n); self.ffft = FloatFFT(n)
        f = (hstep / 65536) / (sstep / 4096)
        self.KX = [0.0] * self.hc; self.KZ = [0.0] * n
        if normals:
            for c in range(n // 2): self.KX[c] = f32v(kTwoPi * c / patch_x * f)
            for r in range(n):
                if r != n // 2: self.KZ[r] = f32v(kTwoPi * s_(r, n) / patch_z * f)
        self.key_modes = []
        for r in range(n):
            if r == n // 2: continue
            for c in range(n // 2):
                if c == 0 and not (1 <= r < n // 2): continue
                self.key_modes.append(r * self.hc + c)
        self.recurrences = {}
    def recurrence(self, D):
        if D not in self.recurrences:
            n, hc = self.n, self.hc
            dt = 1.0 / float(self.R)
            a = [0] * (n * hc)
            for r in range(n):
                kz = kTwoPi * s_(r, n) / self.patch_z
                for c in range(hc):
                    kx = kTwoPi * s_(c, n) / self.patch_x
                    k = math.sqrt(kx * kx + kz * kz)
                    a[r * hc + c] = to_fixed(2.0 * det_cos(det_w(k, self.g, D) * dt), 48)
            self.recurrences[D] = a
        return self.recurrences[D]
    def zero(self):
        m = self.n * self.hc
        return {'pr': [0] * m, 'pi': [0] * m, 'cr': [0] * m, 'ci': [0] * m}
    def model(self, sc):
        return SceneModel(self, sc)
    def advance(self, st, a, steps, first=None):
        for _ in range(steps):
            for key_c, key_p in (('cr', 'pr'), ('ci', 'pi')):
                cur = st[key_c]; prev = st[key_p]
                nxt = [wrap64(mul_sym(a[i], cur[i], 48) - prev[i]) for i in range(len(a))]
                st[key_p] = cur; st[key_c] = nxt
    def choppy_factors(self, lam):
        # 7.1: G_j per choppiness lambda, on modes r != n/2, c < n/2, k > 0 (else 0).
        if lam not in self.G:
            n, hc = self.n, self.hc
            f = (self.hstep / 65536) / (self.sstep / 4096)
            fd = (self.hstep / 65536) / (self.dstep / 65536)
            G = [[0.0] * (n * hc) for _ in range(5)]
            for r in range(n):
                if r == n // 2: continue
                kz = kTwoPi * s_(r, n) / self.patch_z
                for c in range(n // 2):
                    kx = kTwoPi * c / self.patch_x
                    k = math.sqrt(kx * kx + kz * kz)
                    if not (k > 0): continue
                    q = (kx / k, kz / k, (kx * kx) / k, (kz * kz) / k, (kx * kz) / k)
                    for j in range(5):
                        G[j][r * hc + c] = f32v(lam * q[j] * (fd if j < 2 else f))
            self.G[lam] = G
        return self.G[lam]
    def synthesize(self, cr, ci, lam=0.0):
        # 7.2: the state as binary32, the channels present as half-spectra in binary32, in order,
        # synthesized in consecutive pairs A + iB through one binary32 inverse FFT each, then
        # rounded to integers. Returns 8 fields (None where absent).
        n, hc = self.n, self.hc
        m = n * hc
        hr = [f32v(float(v)) for v in cr]; hi = [f32v(float(v)) for v in ci]
        specs = [(0, hr, hi)]
        if self.normals:
            sxr = [0.0] * m; sxi = [0.0] * m; szr = [0.0] * m; szi = [0.0] * m
            for r in range(n):
                for c in range(hc):
                    i = r * hc + c; kx = self.KX[c]; kz = self.KZ[r]
                    sxr[i] = -f32v(kx * hi[i]); sxi[i] = f32v(kx * hr[i])
                    szr[i] = -f32v(kz * hi[i]); szi[i] = f32v(kz * hr[i])
            specs += [(1, sxr, sxi), (2, szr, szi)]
        if self.choppy:
            G = self.choppy_factors(lam)
            for j in range(5):
                g = G[j]
                if j < 2:  # displacement: -i G H
                    re = [f32v(g[i] * hi[i]) for i in range(m)]
                    im = [-f32v(g[i] * hr[i]) for i in range(m)]
                else:      # its derivatives: G H
                    re = [f32v(g[i] * hr[i]) for i in range(m)]
                    im = [f32v(g[i] * hi[i]) for i in range(m)]
                specs.append((3 + j, re, im))
        out = [None] * 8
        scale = 2.0 ** (-2 * self.L)
        limit = 2.0 ** 51 - 1
        def field(x):  # nearest integer to x * 2^-2L, ties to even; saturated; NaN 0
            y = x * scale
            if y != y: return 0
            return int(round(max(-limit, min(limit, y))))
        for p in range(0, len(specs), 2):
            ach, ar, ai = specs[p]
            if p + 1 < len(specs):
                bch, br, bi = specs[p + 1]
            else:
                bch, br, bi = None, [0.0] * m, [0.0] * m
            zr = [[0.0] * n for _ in range(n)]; zi = [[0.0] * n for _ in range(n)]
            for r in range(n):
                rr = (n - r) % n
                for c in range(hc):
                    i = r * hc + c
                    zr[r][c] = f32v(ar[i] - bi[i]); zi[r][c] = f32v(ai[i] + br[i])
                    if 0 < c < n // 2:
                        zr[rr][n - c] = f32v(ar[i] + bi[i]); zi[rr][n - c] = f32v(br[i] - ai[i])
            self.ffft.two(zr, zi)
            out[ach] = [field(zr[r][c]) for r in range(n) for c in range(n)]
            if bch is not None:
                out[bch] = [field(zi[r][c]) for r in range(n) for c in range(n)]
        return out
    def spectrum_of(self, field):
        n, hc = self.n, self.hc
        re = [[field[r * n + c] for c in range(n)] for r in range(n)]; im = [[0] * n for _ in range(n)]
        self.fft.two(re, im, False)
        outr = [0] * (n * hc); outi = [0] * (n * hc)
        for r in range(n):
            for c in range(hc):
                outr[r * hc + c] = re[r][c]; outi[r * hc + c] = im[r][c]
        for c in (0, n // 2):
            for r in range(n // 2 + 1, n):
                outr[r * hc + c] = outr[(n - r) * hc + c]; outi[r * hc + c] = wrap64(-outi[(n - r) * hc + c])
            outi[c] = 0; outi[(n // 2) * hc + c] = 0
        return outr, outi
    def add_correction(self, st, height_corr, lag=0):  # lag: the wake's rule, Waked's business
        field = [0] * (self.n * self.n)
        for pos, v in height_corr:
            field[pos] = wrap64(v << 14)
        dr, di = self.spectrum_of(field)
        for k in ('cr', 'pr'):
            st[k] = [wrap64(x + d) for x, d in zip(st[k], dr)]
        for k in ('ci', 'pi'):
            st[k] = [wrap64(x + d) for x, d in zip(st[k], di)]
    def mirror(self, st):
        n, hc = self.n, self.hc
        for r in range(n // 2 + 1, n):
            for re_k, im_k in (('cr', 'ci'), ('pr', 'pi')):
                st[re_k][r * hc] = st[re_k][(n - r) * hc]; st[im_k][r * hc] = wrap64(-st[im_k][(n - r) * hc])
    def key_state(self, coefs, ps, vs):
        st = self.zero()
        for i, at in enumerate(self.key_modes):
            xr, xi, vr, vi = coefs[i]
            st['cr'][at] = wrap64(xr << ps); st['ci'][at] = wrap64(xi << ps)
            st['pr'][at] = wrap64(st['cr'][at] - wrap64(vr << vs)); st['pi'][at] = wrap64(st['ci'][at] - wrap64(vi << vs))
        self.mirror(st)
        return st
    def floats(self, fields):
        # 7.4: the output floats of every channel present, then (choppy) the Jacobian in float32.
        units = [self.hstep / 65536] + [self.sstep / 4096] * 2 + [self.dstep / 65536 if self.choppy else 0] * 2 + [self.sstep / 4096] * 3
        out = [[f32v(float(v) * units[ch]) for v in fields[ch]] for ch in channels_of(self.normals, self.choppy)]
        if self.choppy:
            xx, zz, xz = out[-3], out[-2], out[-1]
            jac = []
            for i in range(len(xx)):
                a = f32v(1.0 + xx[i]); b = f32v(1.0 + zz[i])
                jac.append(f32v(f32v(a * b) - f32v(xz[i] * xz[i])))
            out.append(jac)
        return out

def f32v(x):  # round a double to float32 (nearest even); exact for the double of a float32 op result
    return struct.unpack('<f', struct.pack('<f', x))[0]

# ---- 7.6 scene model
def mix64(x):
    x = (x + 0x9E3779B97F4A7C15) % M64
    x = ((x ^ (x >> 30)) * 0xBF58476D1CE4E5B9) % M64
    x = ((x ^ (x >> 27)) * 0x94D049BB133111EB) % M64
    return x ^ (x >> 31)

class SceneModel:
    def __init__(self, stream, sc):
        self.sc = sc; n = stream.n; self.n = n; self.R = stream.R
        U = sc['wind_speed_mps']; g = sc['gravity_mps2']; F = sc['fetch_m']
        self.U, self.g, self.A, self.D = U, g, sc['amplitude'], sc['depth_m']
        self.kind = sc['spectrum']; self.spreading = sc['spreading']
        self.wind_angle = sc['wind_dir_deg'] * kPi / 180
        self.wind_cos = det_cos(self.wind_angle); self.wind_sin = det_sin(self.wind_angle)
        self.Lp = U * U / g
        self.l = sc['small_wave_m'] if sc['small_wave_m'] > 0 else 0.5 * max(sc['patch_x_m'] / float(sc['size_x']), sc['patch_z_m'] / float(sc['size_z']))
        try:
            self.alpha = 0.076 * det_pow(g * F / (U * U), -0.22)
        except ZeroDivisionError:
            self.alpha = 0.0
        try:
            self.wp = 22 * det_pow(g * g / (U * F), 1 / 3)
        except ZeroDivisionError:
            self.wp = float('inf')
        unit = stream.hstep / 65536
        scale = float(n) * float(n) / unit
        self.modes = []
        hc = n // 2 + 1
        for r in range(n):
            if r == n // 2: continue
            j = s_(r, n)
            for c in range(n // 2):
                if c == 0 and not (1 <= r < n // 2): continue
                a = self.h0(c, j); h = self.h0(-c, -j); b = (h[0], -h[1])
                SR = (a[0] + b[0]) * scale; SI = (a[1] + b[1]) * scale
                DR = (a[0] - b[0]) * scale; DI = (a[1] - b[1]) * scale
                kz = kTwoPi * float(j) / sc['patch_z_m']; kx = kTwoPi * float(c) / sc['patch_x_m']
                w = det_w(math.sqrt(kx * kx + kz * kz), g, self.D)
                assert abs(SR) + abs(DI) < 2.0 ** 62 and abs(SI) + abs(DR) < 2.0 ** 62
                self.modes.append((r * hc + c, w, SR, SI, DR, DI))
    def P(self, kx, kz, k):
        if k == 0 or self.U == 0 or self.A == 0: return 0.0
        filt = det_exp(((-k) * k) * self.l * self.l)
        if filt == 0: return 0.0
        return (self.phillips(kx, kz, k) if self.kind == 0 else self.jonswap(kx, kz, k)) * filt
    def phillips(self, kx, kz, k):
        kl = k * self.Lp
        cw = (kx * self.wind_cos + kz * self.wind_sin) / k
        k2 = k * k
        return self.A * (0.005 / kPi) * det_exp(-1 / (kl * kl)) / (k2 * k2) * cw * cw
    def jonswap(self, kx, kz, k):
        w = det_w(k, self.g, self.D)
        S = self.freq(w)
        if S == 0: return 0.0
        theta = det_atan2(kz, kx) - self.wind_angle
        return S * self.spread(w, theta) * self.cg(k) / k
    def freq(self, w):
        if w <= 0 or self.U == 0 or self.A == 0: return 0.0
        wp, g = self.wp, self.g
        ratio = wp / w; ratio4 = ratio * ratio * ratio * ratio
        sigma = 0.07 if w <= wp else 0.09
        d = (w - wp) / (sigma * wp)
        pe = det_pow(3.3, det_exp(-0.5 * d * d))
        w2 = w * w
        pm = self.alpha * g * g / (w2 * w2 * w) * det_exp(-1.25 * ratio4)
        return self.A * pm * pe * self.tma(w)
    def tma(self, w):
        if self.D == 0: return 1.0
        wh = w * math.sqrt(self.D / self.g)
        if wh <= 1: return 0.5 * wh * wh
        if wh < 2: return 1 - 0.5 * (2 - wh) * (2 - wh)
        return 1.0
    def cg(self, k):
        w = det_w(k, self.g, self.D); kd = k * self.D
        if self.D == 0 or kd > 20: return 0.5 * w / k
        sech = 1 / det_cosh(kd)
        return self.g * (det_tanh(kd) + kd * sech * sech) / (2 * w)
    def Q(self, s, theta):
        log_q = det_log_gamma(s + 1) - det_log_gamma(s + 0.5) - det_log(2 * math.sqrt(kPi))
        x = 0.5 * det_wrap_angle(theta)
        c = det_sin((kHalfPi - abs(x)) + kHalfPiLo)
        if c == 0: return det_exp(log_q) if s == 0 else 0.0
        return det_exp(log_q + 2 * s * det_log(c))
    def spread(self, w, theta):
        wp, U, g = self.wp, self.U, self.g
        ratio = w / wp
        if self.spreading == 0:
            s_peak = 11.5 * det_pow(g / (wp * U), 2.5)
            s = s_peak * (det_pow(ratio, 5) if ratio <= 1 else det_pow(ratio, -2.5))
            return self.Q(s, theta)
        if self.spreading == 1:
            if 0.56 < ratio and ratio < 0.95: beta = 2.61 * det_pow(ratio, 1.3)
            elif 0.95 <= ratio and ratio < 1.6: beta = 2.28 * det_pow(ratio, -1.3)
            else:
                eps = -0.4 + 0.8393 * det_exp(-0.567 * det_log(ratio * ratio))
                beta = det_pow(10, eps)
            x = beta * det_wrap_angle(theta)
            if not math.isfinite(beta) or abs(x) > 300: return 0.0
            sech = 1 / det_cosh(x)
            return beta / (2 * det_tanh(beta * kPi)) * sech * sech
        s = 6.97 * det_pow(ratio, 4.06) if ratio <= 1 else 9.77 * det_pow(ratio, -2.33 - 1.45 * (U * wp / g - 1.17))
        return self.Q(s, theta)
    def gaussian(self, i, j):
        key = ((i & 0xFFFFFFFF) << 32) | (j & 0xFFFFFFFF)
        a = mix64(self.sc['seed'] ^ mix64(key)); b = mix64(a)
        u1 = float((a >> 11) + 1) * 2.0 ** -53
        u2 = float(b >> 11) * 2.0 ** -53
        r = math.sqrt(-2 * det_log(u1)); phi = kTwoPi * u2
        return (r * det_cos(phi), r * det_sin(phi))
    def h0(self, i, j):
        if i == 0 and j == 0: return (0.0, 0.0)
        if not keeps(self.sc.get('band', (0, 0)), i, j): return (0.0, 0.0)  # 7.7
        dkx = kTwoPi / self.sc['patch_x_m']; dkz = kTwoPi / self.sc['patch_z_m']
        qx = float(i) * dkx; qz = float(j) * dkz
        variance = self.P(qx, qz, math.sqrt(qx * qx + qz * qz)) * dkx * dkz
        if not (variance > 1e-40): return (0.0, 0.0)
        sc = math.sqrt(variance) * 0.5
        xi = self.gaussian(i, j)
        return (xi[0] * sc, xi[1] * sc)
    def t(self, T):
        R = self.R
        sec = T // R  # floor division
        return float(sec) + float(T - sec * R) / float(R)
    def state(self, stream, T):
        st = stream.zero()
        for (X_re, X_im, t) in (('cr', 'ci', self.t(T)), ('pr', 'pi', self.t(T - 1))):
            for (idx, w, SR, SI, DR, DI) in self.modes:
                p = w * t
                C = det_cos(p); S = det_sin(p)
                st[X_re][idx] = to_fixed(SR * C + DI * S, 0)
                st[X_im][idx] = to_fixed(SI * C - DR * S, 0)
        stream.mirror(st)
        return st

# ---- 7.7 cascades, 7.8 cascaded streams
def keeps(band, i, j):
    lo, hi = band
    r2 = i * i + j * j
    return r2 >= lo * lo and (hi == 0 or r2 < hi * hi)

def cascade_scene(sc, cascade, index):
    scale, grid, lo, hi = cascade
    c = dict(sc)
    c['small_wave_m'] = sc['small_wave_m'] if sc['small_wave_m'] > 0 else \
        0.5 * max(sc['patch_x_m'] / float(sc['size_x']), sc['patch_z_m'] / float(sc['size_z']))
    c['patch_x_m'] = sc['patch_x_m'] * float(scale); c['patch_z_m'] = sc['patch_z_m'] * float(scale)
    c['size_x'] = c['size_z'] = grid
    c['seed'] = sc['seed'] ^ ((0x9E3779B97F4A7C15 * index) % M64)
    c['band'] = (lo, hi)
    return c

def cascaded_model_state(sc, cascades, patch_x, patch_z, g, R, hstep, sstep, T):
    # 7.8: each lattice's scene-model state (its own n, patch, band and draws), one after the other.
    stream = Cascaded(cascades, patch_x, patch_z, g, R, hstep, sstep, True, None, False)
    return stream.model(sc).state(stream, T)

class Cascaded:
    """7.8: a stream of lattices, one per cascade; states, fields and items one lattice after the
    other. Offers what Decoder uses of a Stream."""
    def __init__(self, cascades, patch_x, patch_z, gravity, R, hstep, sstep, normals, dstep, choppy):
        self.cascades = cascades
        self.lattices = [Stream(c[1], patch_x * float(c[0]), patch_z * float(c[0]), gravity, R, hstep, sstep, normals, dstep, choppy)
                         for c in cascades]
        first = self.lattices[0]
        self.L = first.L  # the CRC's grid_log2: the first lattice's
        self.normals, self.choppy, self.cascaded = normals, choppy, True
        self.hstep, self.sstep, self.dstep = hstep, sstep, dstep
        self.modes_at, self.samples_at, self.key_modes = [], [], []
        m = p = 0
        for lat in self.lattices:
            self.modes_at.append(m); self.samples_at.append(p)
            self.key_modes += [m + i for i in lat.key_modes]
            m += lat.modes; p += lat.samples
        self.modes, self.samples = m, p
    def parts(self, st):  # each lattice's slice of a state
        return [{k: v[a:a + lat.modes] for k, v in st.items()} for lat, a in zip(self.lattices, self.modes_at)]
    def joined(self, sts):
        return {k: sum((st[k] for st in sts), []) for k in ('pr', 'pi', 'cr', 'ci')}
    def recurrence(self, D):
        return sum((lat.recurrence(D) for lat in self.lattices), [])
    def zero(self):
        return self.joined([lat.zero() for lat in self.lattices])
    def advance(self, st, a, steps, first=None):
        Stream.advance(self, st, a, steps)  # per mode: the lattices need no telling apart
    def model(self, sc):
        return CascadedModel(self, sc)
    def synthesize(self, cr, ci, lam=0.0):
        out = [None] * 8
        for lat, a in zip(self.lattices, self.modes_at):
            part = lat.synthesize(cr[a:a + lat.modes], ci[a:a + lat.modes], lam)
            for ch in range(8):
                if part[ch] is not None: out[ch] = (out[ch] or []) + part[ch]
        return out
    def add_correction(self, st, height_corr, lag=0):
        parts = self.parts(st)
        for lat, p, part in zip(self.lattices, self.samples_at, parts):
            mine = [(pos - p, v) for pos, v in height_corr if p <= pos < p + lat.samples]
            if mine: lat.add_correction(part, mine)
        st.update(self.joined(parts))
    def key_state(self, coefs, ps, vs):
        sts, at = [], 0
        for lat in self.lattices:
            sts.append(lat.key_state(coefs[at:at + len(lat.key_modes)], ps, vs)); at += len(lat.key_modes)
        return self.joined(sts)
    def floats(self, fields):
        return Stream.floats(self, fields)  # per sample

class CascadedModel:
    """7.8: lattice l's modes are cascade l's scene (7.7) on its own lattice."""
    def __init__(self, stream, sc):
        self.s = stream
        self.models = [SceneModel(lat, cascade_scene(sc, c, index)) for index, (lat, c) in enumerate(zip(stream.lattices, stream.cascades))]
    def state(self, stream, T):
        return stream.joined([m.state(lat, T) for m, lat in zip(self.models, stream.lattices)])

# ---- 7.9 the wake lattice
def div_round_sym(v, d):  # v / d rounded half away from zero
    q = (abs(v) + d // 2) // d
    return q if v >= 0 else -q

def damped(w, g, dt):  # a, b and stay (7.9)
    if w > g:
        wd = math.sqrt(w * w - g * g); e = det_exp_neg(g * dt)
        c = det_cos(wd * dt); s = det_sin(wd * dt)
        return 2.0 * e * c, det_exp_neg(2.0 * g * dt), e * (c + g * (s / wd))
    r = math.sqrt(g * g - w * w)
    if g + r == 0.0: return 2.0, 1.0, 1.0
    slow = det_exp_neg(w * w / (g + r) * dt); fast = det_exp_neg((g + r) * dt)
    sd = det_exp_neg(g * dt) * dt if r * dt < 1e-8 else 0.5 * (slow - fast) / r
    return slow + fast, det_exp_neg(2.0 * g * dt), 0.5 * (slow + fast) + g * sd

def present_at(presence, t):  # 7.9 presence (version 7): whether a hull presses at t seconds
    start, length, every = presence
    u = t - start
    if every > 0.0:
        u = math.fmod(u, every)
        if u < 0.0: u += every
        return u < length
    return t >= start and (length == math.inf or u < length)

def pose_at(v, t):  # model/vessel_track.cpp: (x, z, dir_x, dir_z) at t seconds
    p = v['points']
    def heading_of(a, b, prev):
        dx = b[1] - a[1]; dz = b[2] - a[2]
        if dx == 0.0 and dz == 0.0: return prev
        length = math.sqrt(dx * dx + dz * dz)
        return (dx / length, dz / length)
    x, z = p[0][1], p[0][2]
    if len(p) == 1: return x, z, 1.0, 0.0
    heading = (1.0, 0.0)
    rng = range(1, len(p)) if v['repeat'] else range(len(p) - 1, 0, -1)
    for i in rng: heading = heading_of(p[i - 1], p[i], heading)
    period = p[-1][0]
    if v['repeat'] and t > period: t = math.fmod(t, period)
    if t <= 0.0: return x, z, heading[0], heading[1]
    for i in range(1, len(p)):
        heading = heading_of(p[i - 1], p[i], heading)
        if t <= p[i][0] or i + 1 == len(p):
            f = min(1.0, (t - p[i - 1][0]) / (p[i][0] - p[i - 1][0]))
            return p[i - 1][1] + f * (p[i][1] - p[i - 1][1]), p[i - 1][2] + f * (p[i][2] - p[i - 1][2]), heading[0], heading[1]
    return x, z, heading[0], heading[1]

def walk(n, q, m):  # 7.9: m e^{-i s q} per signed bin s
    def direct(b): return (m * det_cos(float(b) * q), -(m * det_sin(float(b) * q)))
    out = [None] * n
    for sign, count in ((1, n // 2), (-1, n // 2 + 1)):
        u = (det_cos(q), -det_sin(q)) if sign > 0 else (det_cos(q), det_sin(q))
        v = None
        for i in range(count):
            if i % 16 == 0: v = direct(sign * i)
            else: v = (v[0] * u[0] - v[1] * u[1], v[0] * u[1] + v[1] * u[0])
            if sign > 0: out[i] = v
            elif i > 0: out[n - i] = v
    return out, direct(-(n // 2))  # the rows in FFT order; the last column (bin -n/2), taken directly

def hull_pressure(lat, v, x, z, dx, dz, scale, out):  # model/hull_pressure.cpp in the Det arithmetic
    n, hc, size = lat.n, lat.hc, lat.patch_x
    sa = 0.25 * v['length_m']; sc = 0.25 * v['beam_m']
    peak = v['draft_m'] * (kTwoPi * sa * sc) / (size * size)
    cols, last = walk(n, kTwoPi / size * x, 1.0)
    col = cols[:n // 2] + [last]
    rows, _ = walk(n, kTwoPi / size * z, scale)
    for r in range(n):
        rr, ri = rows[r]
        kz = kTwoPi * s_(r, n) / size
        for c in range(hc):
            kx = kTwoPi * s_(c, n) / size
            ka = kx * dx + kz * dz; kc = kz * dx - kx * dz
            e = peak * det_exp(-(0.5 * (sa * sa * (ka * ka) + sc * sc * (kc * kc))))
            kr, ki = col[c]
            re = rr * kr - ri * ki; im = rr * ki + ri * kr
            o = out[r * hc + c]
            out[r * hc + c] = (o[0] + re * e, o[1] + im * e)

def forcing_units(x):
    if x != x: return 0
    if x >= 2.0 ** 62: return 1 << 62
    if x <= -2.0 ** 62: return -(1 << 62)
    return math.floor(x + 0.5)

class Waked:
    """7.9: the sea's lattices (a Stream or Cascaded) and then the wake lattice, whose modes start at
    rest, ring down by the damped recurrence and take a delta's corrections as motion."""
    def __init__(self, sea, wake, gravity, R, hstep, sstep, normals, dstep, choppy):
        grid, size, self.ox, self.oz, self.decay, self.visc, self.epoch = wake
        self.vessels = []; self.pressures = {}
        self.sea = sea
        self.wake = Stream(grid, size, size, gravity, R, hstep, sstep, normals, dstep, choppy)
        self.L, self.normals, self.choppy, self.cascaded = sea.L, normals, choppy, sea.cascaded
        self.hstep, self.sstep, self.dstep = hstep, sstep, dstep
        self.wake_at, self.wake_samples_at = sea.modes, sea.samples
        self.modes, self.samples = sea.modes + self.wake.modes, sea.samples + self.wake.samples
        self.key_modes = sea.key_modes + [sea.modes + i for i in self.wake.key_modes]
        self.recurrences = {}
    def parts(self, st):
        return ({k: v[:self.wake_at] for k, v in st.items()}, {k: v[self.wake_at:] for k, v in st.items()})
    def joined(self, sea, wake):
        return {k: sea[k] + wake[k] for k in ('pr', 'pi', 'cr', 'ci')}
    def recurrence(self, D):
        if D not in self.recurrences:
            w = self.wake; n, hc = w.n, w.hc
            dt = 1.0 / float(w.R)
            a, b = [0] * (n * hc), [0] * (n * hc)
            alpha, beta = [0.0] * (n * hc), [0.0] * (n * hc)
            for r in range(n):
                kz = kTwoPi * s_(r, n) / w.patch_z
                for c in range(hc):
                    kx = kTwoPi * s_(c, n) / w.patch_x
                    k = math.sqrt(kx * kx + kz * kz)
                    g = self.decay + 2.0 * self.visc * (k * k)
                    x, y, stay = damped(det_w(k, w.g, D), g, dt)
                    a[r * hc + c] = to_fixed(x, 48); b[r * hc + c] = to_fixed(y, 48)
                    if r != n // 2 and c != n // 2:
                        alpha[r * hc + c] = x - y - stay; beta[r * hc + c] = stay - 1.0
            self.recurrences[D] = (self.sea.recurrence(D), a, b, alpha, beta)
        return self.recurrences[D]
    def zero(self):
        return self.joined(self.sea.zero(), self.wake.zero())
    def pressure(self, t):  # the hulls during the step from tick t, in units x n^2 (7.9)
        if t not in self.pressures:
            w = self.wake
            out = [(0.0, 0.0)] * w.modes
            scale = float(w.n) * float(w.n) / (self.hstep / 65536.0)
            for v in self.vessels:
                if not present_at(v['presence'], (float(t) + 0.5) / float(w.R)): continue
                x, z, dx, dz = pose_at(v, (float(t) + 0.5) / float(w.R))
                hull_pressure(w, v, x - self.ox, z - self.oz, dx, dz, scale, out)
            self.pressures[t] = out
        return self.pressures[t]
    def step_wake(self, wake, rec, steps, first, lo, hi):  # forced only for ticks in [lo, hi)
        _, a, b, alpha, beta = rec
        m = len(a)
        for step in range(steps):
            t = first + step
            fr, fi = [0.0] * m, [0.0] * m
            if self.vessels and lo <= t - 1 < hi:
                p0 = self.pressure(t - 1)
                fr = [alpha[i] * p0[i][0] for i in range(m)]; fi = [alpha[i] * p0[i][1] for i in range(m)]
            if self.vessels and lo <= t < hi:
                p1 = self.pressure(t)
                fr = [fr[i] + beta[i] * p1[i][0] for i in range(m)]; fi = [fi[i] + beta[i] * p1[i][1] for i in range(m)]
            for key_c, key_p, f in (('cr', 'pr', fr), ('ci', 'pi', fi)):
                cur = wake[key_c]; prev = wake[key_p]
                nxt = [wrap64(wrap64(mul_sym(a[i], cur[i], 48) - mul_sym(b[i], prev[i], 48)) + forcing_units(f[i])) for i in range(m)]
                wake[key_p] = cur; wake[key_c] = nxt
    def advance(self, st, rec, steps, first=None):
        sea, wake = self.parts(st)
        self.sea.advance(sea, rec[0], steps)
        self.step_wake(wake, rec, steps, first, 0, 1 << 63)
        st.update(self.joined(sea, wake))
    def model(self, sc):
        sea_model = self.sea.model(sc)
        stream = self
        class Model:
            def state(self, _s, T):
                return stream.joined(sea_model.state(stream.sea, T), stream.wake.zero())
        return Model()
    def synthesize(self, cr, ci, lam=0.0):
        a = self.wake_at
        sea = self.sea.synthesize(cr[:a], ci[:a], lam)
        wake = self.wake.synthesize(cr[a:], ci[a:], lam)
        return [None if s is None else s + w for s, w in zip(sea, wake)]
    def add_correction(self, st, height_corr, lag=0):
        sea, wake = self.parts(st)
        p = self.wake_samples_at
        mine = [(pos, v) for pos, v in height_corr if pos < p]
        if mine: self.sea.add_correction(sea, mine)
        field = [0] * self.wake.samples
        for pos, v in height_corr:
            if pos >= p: field[pos - p] = wrap64(v << 14)
        dr, di = self.wake.spectrum_of(field)
        for kc, kp, d in (('cr', 'pr', dr), ('ci', 'pi', di)):
            wake[kc] = [wrap64(x + y) for x, y in zip(wake[kc], d)]
            wake[kp] = [wrap64(x + (y - div_round_sym(y, 4 * lag) if lag else y)) for x, y in zip(wake[kp], d)]
        st.update(self.joined(sea, wake))
    def key_state(self, coefs, ps, vs):
        k = len(self.sea.key_modes)
        return self.joined(self.sea.key_state(coefs[:k], ps, vs), self.wake.key_state(coefs[k:], ps, vs))
    def floats(self, fields):
        return Stream.floats(self, fields)  # per sample

def hash_state(st):
    h = 1469598103934665603
    for k in ('pr', 'pi', 'cr', 'ci'):
        for x in st[k]:
            for b in struct.pack('<q', x):
                h ^= b; h = (h * 1099511628211) % M64
    return h

# ---- 7.5 timeline + 9 decoder
SHIFT = [14, 10, 10, 14, 14, 10, 10, 10]  # 7.4: heights and displacement in quarter steps << 14, the rest << 10

class Decoder:
    def __init__(self, stream, max_payload, history, max_lag, max_pending=8):
        self.s = stream; self.max_payload = max_payload; self.history = history; self.max_lag = max_lag
        self.max_pending = max_pending
        self.scenes = {}  # from -> (tag, params, model or None)
        self.states = {}; self.pending = {}
        self.completed = None
    def add_scene(self, frm, tag, params):
        self.scenes[frm] = [tag, params, None]
    def start_of(self, t):
        c = [f for f in self.scenes if f <= t]
        return max(c) if c else None
    def model(self, frm):
        e = self.scenes[frm]
        if e[2] is None:
            e[2] = self.s.model(e[1])
        return e[2]
    def model_state(self, t):
        st = self.model(self.start_of(t)).state(self.s, t)
        if isinstance(self.s, Waked) and self.s.vessels:  # 7.9: the last two epochs' wake
            k = t // self.s.epoch
            sea, wake = self.s.parts(st)
            for e in range(max(0, k - 1), k + 1):
                p = self.wake_part(e, t)
                wake = {key: [wrap64(x + y) for x, y in zip(wake[key], p[key])] for key in wake}
            st = self.s.joined(sea, wake)
        return st
    def rec_near(self, t):  # the recurrence of the scene in force at t (the oldest held before it)
        return self.s.recurrence(self.scenes[self.start_of(max(t, min(self.scenes)))][1]['depth_m'])
    def wake_part(self, e, t):  # 7.9: epoch e's wake at tick t, from rest at e E, forced during e
        ep = self.s.epoch
        if not hasattr(self, 'parts'): self.parts = {}
        p = self.parts.get(e)
        if p is None or p['at'] > t:
            p = {'at': e * ep, 'st': self.s.wake.zero()}; self.parts[e] = p
        while p['at'] < t:
            nxt = min([t] + [f for f in self.scenes if p['at'] < f < t])
            self.s.step_wake(p['st'], self.rec_near(p['at']), nxt - p['at'], p['at'], e * ep, (e + 1) * ep)
            p['at'] = nxt
        return p['st']
    def walk(self, st, frm, to):  # 7.9: scene by scene, dropping epoch B/E - 2 at each boundary B
        now = frm
        while now < to:
            nxt = min([to] + [f for f in self.scenes if now < f < to])
            if self.s.vessels: nxt = min(nxt, (now // self.s.epoch + 1) * self.s.epoch)
            self.s.advance(st, self.rec_near(now), nxt - now, now)
            now = nxt
            if self.s.vessels and now % self.s.epoch == 0 and now // self.s.epoch >= 2:
                gone = self.wake_part(now // self.s.epoch - 2, now)
                sea, wake = self.s.parts(st)
                wake = {key: [wrap64(x - y) for x, y in zip(wake[key], gone[key])] for key in wake}
                st.update(self.s.joined(sea, wake))
        return st
    def choppiness(self, t):  # lambda of the scene in force at t (7.2)
        return self.scenes[self.start_of(t)][1]['choppiness']
    def advance(self, st, frm, to):
        now = frm
        E = self.start_of(to)
        if isinstance(self.s, Waked):
            # 7.9: the wake rides through a change; the sea takes the new scene's model state
            if E > frm:
                st = self.walk(st, frm, E)
                fresh = self.model(E).state(self.s, E)
                st = self.s.joined(self.s.parts(fresh)[0], self.s.parts(st)[1]); now = E
            return self.walk(st, now, to)
        if E > frm:
            st = self.model_state(E); now = E
        self.s.advance(st, self.s.recurrence(self.scenes[self.start_of(now)][1]['depth_m']), to - now, now)
        return st
    def accept(self, env, payload):
        self.completed = None
        tick, baseline, key, index, count = env
        s = self.s
        h = parse_payload(env, payload, self.max_payload, s.L)
        S = len(s.key_modes) if h['key'] and not h['modeled'] else 0
        total = S + s.samples
        if h['whole']:
            h['begin'], h['end'] = 0, total
        if h['normals'] != s.normals or h['choppy'] != s.choppy or h['cascaded'] != s.cascaded or h['wake'] != isinstance(s, Waked):
            raise Refused('wrong_dimensions')
        if h['begin'] >= h['end'] or h['end'] > total: raise Refused('bad_range')
        if h['key'] and not h['modeled'] and (h['pos_shift'] > 40 or h['vel_shift'] > 40): raise Refused('bad_value')
        if count == 0 or count > 4096 or index >= count: raise Refused('bad_index')
        if (baseline != tick) if key else (baseline >= tick): raise Refused('bad_baseline')
        if not key and tick - baseline > self.max_lag: raise Refused('lag_too_large')
        st0 = self.start_of(tick)
        if st0 is None or self.scenes[st0][0] != h['tag']: raise Refused('unknown_scene')
        newest = max(self.states) if self.states else None
        if newest is not None and tick <= newest and newest - tick >= self.history: raise Refused('stale_tick')
        if tick in self.states: raise Refused('duplicate_chunk')
        if not key and baseline not in self.states: raise Refused('unknown_baseline')
        p = self.pending.get(tick)
        if p is not None:
            if p['key'] != key or p['modeled'] != h['modeled'] or p['baseline'] != baseline or p['count'] != count:
                raise Refused('inconsistent_frame')
            if index in p['got']: raise Refused('duplicate_chunk')
            covered = h['end'] - h['begin']
            for b, e in p['ranges']:
                if h['begin'] < e and b < h['end']: raise Refused('overlapping_range')
                covered += e - b
            if len(p['got']) + 1 == count and covered != total: raise Refused('coverage_mismatch')
        elif count == 1 and not h['whole']:
            raise Refused('coverage_mismatch')
        keyc, corr = decode_body(S, s.samples, s.normals, s.choppy, h['begin'], h['end'], h['body'])
        if p is None:
            p = {'key': key, 'modeled': h['modeled'], 'baseline': baseline, 'count': count, 'got': set(), 'ranges': [],
                 'coefs': {}, 'corr': [[] for _ in range(8)], 'ps': h.get('pos_shift'), 'vs': h.get('vel_shift')}
            if not (key and not h['modeled']):
                if key:
                    p['state'] = self.model_state(tick)
                else:
                    st = {k: list(v) for k, v in self.states[baseline].items()}
                    p['state'] = self.advance(st, baseline, tick)
                p['fields'] = s.synthesize(p['state']['cr'], p['state']['ci'], self.choppiness(tick))
            self.pending[tick] = p
        p['got'].add(index); p['ranges'].append((h['begin'], h['end']))
        for i, k in enumerate(keyc): p['coefs'][h['begin'] + i] = k
        for ch in range(8):
            p['corr'][ch].extend(corr[ch])
            if 'fields' in p:
                for pos, v in corr[ch]:
                    p['fields'][ch][pos] = wrap64(p['fields'][ch][pos] + (v << SHIFT[ch]))
        if len(p['got']) == count:
            if key and not p['modeled']:
                p['state'] = s.key_state([p['coefs'][i] for i in range(len(s.key_modes))], p['ps'], p['vs'])
                p['fields'] = s.synthesize(p['state']['cr'], p['state']['ci'], self.choppiness(tick))
                for ch in range(8):
                    for pos, v in p['corr'][ch]:
                        p['fields'][ch][pos] = wrap64(p['fields'][ch][pos] + (v << SHIFT[ch]))
            if p['corr'][0]:
                s.add_correction(p['state'], p['corr'][0], 0 if key else tick - baseline)
            self.states[tick] = p['state']
            del self.pending[tick]
            self.completed = (tick, p['fields'])
            newest = max(self.states)
            if newest >= self.history:
                oldest = newest - self.history
                for t in [t for t in self.states if t < oldest]: del self.states[t]
                for t in [t for t in self.pending if t < oldest]: del self.pending[t]
        while len(self.pending) > self.max_pending:
            del self.pending[min(self.pending)]

# ---- PROTOCOL.md 7.1
def varint64(b, pos):
    v = 0
    for i in range(10):
        if pos >= len(b): raise Refused('truncated')
        x = b[pos]; pos += 1
        if i == 9 and x > 1: raise Refused('truncated')
        v |= (x & 0x7F) << (7 * i)
        if not x & 0x80: return v, pos
    raise Refused('truncated')

def decode_block(b):
    if not b: raise Refused('empty')
    newest, pos = varint64(b, 0)
    out = []
    while pos < len(b):
        if len(out) == 64: raise Refused('out_of_range')
        back, pos = varint64(b, pos); lag, pos = varint64(b, pos); cm1, pos = varint64(b, pos)
        if back > newest: raise Refused('bad_sequence')
        tick = newest - back
        if lag > 1024 or lag > tick: raise Refused('bad_sequence')
        if cm1 >= 4096: raise Refused('bad_chunk_index')
        index = 0
        if cm1 > 0: index, pos = varint64(b, pos)
        if index > cm1: raise Refused('bad_chunk_index')
        length, pos = varint64(b, pos)
        if length > len(b) - pos: raise Refused('truncated')
        out.append(((tick, tick - lag, lag == 0, index, cm1 + 1), b[pos:pos + length])); pos += length
    if not out: raise Refused('empty')
    return out


# -- minimal FlatBuffers reading (size-prefixed root), enough for Welcome and SceneUpdate
def u32(b, o): return struct.unpack_from('<I', b, o)[0]
def table_field(b, t, slot, fmt, default):
    vt = t - struct.unpack_from('<i', b, t)[0]
    vt_len = struct.unpack_from('<H', b, vt)[0]
    off_pos = 4 + 2 * slot
    if off_pos >= vt_len: return default
    off = struct.unpack_from('<H', b, vt + off_pos)[0]
    if off == 0: return default
    return struct.unpack_from(fmt, b, t + off)[0]
def table_ref(b, t, slot):
    vt = t - struct.unpack_from('<i', b, t)[0]
    vt_len = struct.unpack_from('<H', b, vt)[0]
    off_pos = 4 + 2 * slot
    if off_pos >= vt_len: return None
    off = struct.unpack_from('<H', b, vt + off_pos)[0]
    if off == 0: return None
    return t + off + u32(b, t + off)
def message(b):
    assert u32(b, 0) == len(b) - 4 and b[8:12] == b'OCNP'
    buf = b[4:]
    root = u32(buf, 0)
    version = table_field(buf, root, 0, '<H', 0)
    body_type = table_field(buf, root, 1, '<B', 0)
    body = table_ref(buf, root, 2)
    return buf, version, body_type, body
SCENE = [('size_x', '<H', 0), ('size_z', '<H', 0), ('patch_x_m', '<d', 0.0), ('patch_z_m', '<d', 0.0), ('spectrum', '<B', 0),
         ('spreading', '<B', 0), ('wind_speed_mps', '<d', 0.0), ('wind_dir_deg', '<d', 0.0), ('fetch_m', '<d', 0.0),
         ('amplitude', '<d', 0.0), ('depth_m', '<d', 0.0), ('small_wave_m', '<d', 0.0), ('choppiness', '<d', 0.0),
         ('gravity_mps2', '<d', 0.0), ('seed', '<Q', 0)]
STREAM = [('profile_id', '<B', 0), ('grid', '<H', 0), ('patch_x_m', '<d', 0.0), ('patch_z_m', '<d', 0.0), ('gravity_mps2', '<d', 0.0),
          ('depth_m', '<d', 0.0), ('rate_hz', '<H', 0), ('height_step_m', '<f', 0.0), ('slope_step', '<f', 0.0),
          ('disp_step_m', '<f', 0.0), ('normals', '<B', 0), ('choppy', '<B', 0)]
WAKE = [('grid', '<H', 0), ('size_m', '<d', 0.0), ('origin_x_m', '<d', 0.0), ('origin_z_m', '<d', 0.0), ('decay_per_s', '<d', 0.0),
        ('viscosity_m2ps', '<d', 0.0), ('epoch_ticks', '<I', 0)]
def read_wake(buf, stream_table):
    # StreamParams slot 13: table WakeLattice (PROTOCOL.md 8); absent: no wake.
    t = table_ref(buf, stream_table, 13)
    if t is None: return None
    w = read_table(buf, t, WAKE)
    return tuple(w[name] for name, _, _ in WAKE)
def read_vessels(buf, welcome_table, slot=12):
    # Welcome slot 12 (SceneUpdate slot 5): a vector of tables Vessel {id:uint32, length_m, beam_m, draft_m:double,
    # repeat:bool, waypoints:[struct Waypoint {t_s, x_m, z_m:double}], present_from_s = -inf,
    # present_for_s = inf, present_every_s = 0:double} (PROTOCOL.md 8).
    v = table_ref(buf, welcome_table, slot)
    if v is None: return []
    out = []
    for i in range(u32(buf, v)):
        at = v + 4 + 4 * i
        t = at + u32(buf, at)
        w = table_ref(buf, t, 5)
        points = [struct.unpack_from('<ddd', buf, w + 4 + 24 * j) for j in range(u32(buf, w))] if w is not None else []
        out.append({'id': table_field(buf, t, 0, '<I', 0), 'length_m': table_field(buf, t, 1, '<d', 0.0),
                    'beam_m': table_field(buf, t, 2, '<d', 0.0), 'draft_m': table_field(buf, t, 3, '<d', 0.0),
                    'repeat': bool(table_field(buf, t, 4, '<B', 0)), 'points': points,
                    'presence': (table_field(buf, t, 6, '<d', -math.inf), table_field(buf, t, 7, '<d', math.inf),
                                 table_field(buf, t, 8, '<d', 0.0))})
    return out
def read_table(buf, t, spec):
    return {name: table_field(buf, t, i, fmt, d) for i, (name, fmt, d) in enumerate(spec)}
def read_cascades(buf, stream_table):
    # StreamParams slot 12: a vector of struct Cascade {patch_scale:uint8, (pad), grid, band_min,
    # band_max:uint16}, 8 bytes each; absent: no cascades.
    v = table_ref(buf, stream_table, 12)
    if v is None: return []
    return [struct.unpack_from('<BxHHH', buf, v + 4 + 8 * i) for i in range(u32(buf, v))]

def parse(path):
    lines = []
    for text in open(path):
        text = text.rstrip('\n')
        if not text or text.startswith('#'): continue
        words = text.split(' ')
        lines.append((words[0], dict(w.split('=', 1) for w in words[1:])))
    return lines

def f32(text): return struct.unpack('<f', struct.pack('<f', float(text)))[0]

def fnv1a64(data):
    h = 0xcbf29ce484222325
    for b in data:
        h ^= b; h = (h * 0x100000001b3) % (1 << 64)
    return h

def run(name):
    lines = parse(os.path.join(HERE, name + '.txt'))
    f32_path = os.path.join(HERE, name + '.f32')  # absent for desktop_cascaded: FNV-1a alone
    floats = open(f32_path, 'rb').read() if os.path.exists(f32_path) else None
    dec = None; last = None; stream = None
    ok = 0
    for kind, f in lines:
        if kind == 'welcome':
            buf, version, bt, body = message(bytes.fromhex(f['hex']))
            assert version == 4 and bt == 2, (version, bt)
            w = {'stream': read_table(buf, table_ref(buf, body, 1), STREAM), 'cascades': read_cascades(buf, table_ref(buf, body, 1)),
                 'wake': read_wake(buf, table_ref(buf, body, 1)), 'vessels': read_vessels(buf, body), 'scene': read_table(buf, table_ref(buf, body, 2), SCENE),
                 'tick_period_s': table_field(buf, body, 6, '<d', 0.0), 'max_message_bytes': table_field(buf, body, 9, '<I', 0),
                 'current_tick64': table_field(buf, body, 10, '<Q', 0), 'scene_serial': table_field(buf, body, 11, '<I', 0),
                 'current_tick': table_field(buf, body, 5, '<I', None)}
            assert w['current_tick'] is None  # v1 field absent
            last = ('welcome', w)
        elif kind == 'stream':
            w = last[1]; st = w['stream']
            R = round(1 / w['tick_period_s'])
            assert int(f['tick_rate_hz']) == R
            for k in ('profile_id', 'grid', 'rate_hz', 'normals', 'choppy'): assert int(f[k]) == st[k], k
            for k in ('patch_x_m', 'patch_z_m', 'gravity_mps2', 'depth_m'): assert float(f[k]) == st[k], k
            for k in ('height_step_m', 'slope_step', 'disp_step_m'): assert f32(f[k]) == st[k], k
            assert int(f['max_payload']) == max(1100, w['max_message_bytes'] - 96)
            cascades = w['cascades']
            assert f.get('cascades', '') == ','.join(':'.join(str(x) for x in c) for c in cascades)
            kind_ = Cascaded if cascades else Stream
            first = [cascades] if cascades else [st['grid']]
            stream = kind_(*first, st['patch_x_m'], st['patch_z_m'], st['gravity_mps2'], R, st['height_step_m'], st['slope_step'], bool(st['normals']),
                           st['disp_step_m'], bool(st['choppy']))
            if cascades: assert cascades[0][1] == st['grid']
            wake = w['wake']
            assert f.get('wake', '') == (':'.join('%.17g' % x if isinstance(x, float) else str(x) for x in wake) if wake else '')
            if wake:
                stream = Waked(stream, wake, st['gravity_mps2'], R, st['height_step_m'], st['slope_step'], bool(st['normals']),
                               st['disp_step_m'], bool(st['choppy']))
                stream.vessels = w['vessels']
            dec = Decoder(stream, int(f['max_payload']), int(f['history_ticks']), int(f['max_lag']))
        elif kind == 'scene_update':
            buf, version, bt, body = message(bytes.fromhex(f['hex']))
            assert version == 4 and bt == 10
            u = {'scene': read_table(buf, table_ref(buf, body, 2), SCENE), 'effective_tick64': table_field(buf, body, 3, '<Q', 0),
                 'serial': table_field(buf, body, 4, '<I', 0)}
            if table_ref(buf, body, 5) is not None:  # SceneUpdate.vessels (slot 5): the fleet from its tick on
                dec.s.vessels = read_vessels(buf, body, 5)
                dec.s.pressures = {}; dec.parts = {}  # computed again with it: the same integers (7.9)
            last = ('update', u)
        elif kind == 'scene':
            kind0, m = last
            frm = 0 if kind0 == 'welcome' else m['effective_tick64']
            serial = m['scene_serial'] if kind0 == 'welcome' else m['serial']
            assert int(f['from']) == frm and int(f['serial']) == serial and int(f['tag']) == serial % 256
            for name_, fmt, d in SCENE:
                assert (float(f[name_]) if fmt == '<d' else int(f[name_])) == m['scene'][name_], name_
            dec.add_scene(frm, serial % 256, m['scene'])
        elif kind == 'model':
            t = int(f['tick'])
            st = dec.model_state(t)
            assert dec.scenes[dec.start_of(t)][0] == int(f['tag'])
            got = '%016x' % hash_state(st)
            assert got == f['state_hash'], (t, got, f['state_hash'])
            ok += 1
        elif kind == 'chunk':
            dg = bytes.fromhex(f['datagram'])
            assert dg[0] == 1
            recs = decode_block(dg[1:])
            assert len(recs) == 1
            env, payload = recs[0]
            assert env == (int(f['tick']), int(f['baseline']), f['key'] == '1', int(f['index']), int(f['count']))
            assert payload == bytes.fromhex(f['payload'])
            try:
                dec.accept(env, payload); res = 'ok'
            except Refused as e:
                res = str(e)
            assert res == f['expect'], (f['what'], res, f['expect'])
            ok += 1
        elif kind == 'frame':
            t = int(f['tick'])
            assert dec.completed and dec.completed[0] == t
            fields = dec.completed[1]
            out = stream.floats(fields)
            labels = ['height', 'slope_x', 'slope_z'] + (['disp_x', 'disp_z', 'disp_xx', 'disp_zz', 'disp_xz', 'jacobian'] if stream.choppy else [])
            assert len(out) == len(labels)
            data = b''.join(struct.pack('<%df' % len(v), *v) for v in out)
            positions = [int(x) for x in f['samples'].split(',')]
            for label, v in zip(labels, out):
                assert [f32(x) for x in f[label].split(',')] == [v[i] for i in positions], (t, label)
            assert len(f['corrections'].split(',')) == (3 if stream.choppy else 2)
            assert len(data) == int(f['bytes'])
            if 'offset' in f:
                off = int(f['offset'])
                assert data == floats[off:off + len(data)], 'frame %d floats differ' % t
            assert '%016x' % fnv1a64(data) == f['fnv1a64']
            assert '%016x' % hash_state(dec.states[t]) == f['state_hash'], 'state hash %d' % t
            ok += 1
    print(name, 'ok:', ok, 'checks')


def tables(big):
    vals = [(det_log(10), '0x1.26bb1bbb55516p+1'), (det_log(0.3), '-0x1.34378fcbda721p+0'), (det_exp(-1.5), '0x1.c8f87724b5c1dp-3'),
            (det_exp(700.5), '0x1.8625c7d4f56c2p+1010'), (det_pow(3.3, 0.7), '0x1.273c7cfb01256p+1'), (det_pow(0.49, -2.5), '0x1.7ccb3107ef8ccp+2'),
            (det_atan2(1, -2), '0x1.56c6e7397f5aep+1'), (det_atan2(-3, 0.5), '-0x1.67d8863bc99bcp+0'), (det_log_gamma(0.3), '0x1.188637a6c41bp+0'),
            (det_log_gamma(150000.5), '0x1.8fd7f8141209ap+20'), (det_cosh(2.5), '0x1.88776e4b30aa3p+2'), (det_wrap_angle(100), '-0x1.0fdaa22168cp-1'),
            (det_cos(2e9), '0x1.9dcefc534b5a6p-2'), (det_sin(2e9), '0x1.d454ed4068727p-1')]
    for v, want in vals:
        assert v == float.fromhex(want), (v.hex(), want)
    print('12.1 ok')
    hstep = struct.unpack('<f', struct.pack('<f', 0.01))[0]
    def scene(**kw):
        s = dict(size_x=256, size_z=256, patch_x_m=256.0, patch_z_m=256.0, spectrum=0, spreading=0, wind_speed_mps=10.0, wind_dir_deg=0.0,
                 fetch_m=1e5, amplitude=1.0, depth_m=0.0, small_wave_m=0.0, choppiness=0.0, gravity_mps2=9.81, seed=1)
        s.update(kw); return s
    cases = [(scene(), 32, 12345, '2f726301f7d8c51c'),
             (scene(spectrum=1, spreading=0, wind_dir_deg=37.0), 64, 76000000000, '9c5d5fe2d2c38ca4'),
             (scene(spectrum=1, spreading=2, depth_m=8.0), 32, 0, 'd846add969297da3'),
             (scene(spectrum=1, spreading=1, wind_speed_mps=4.0, fetch_m=5e6, seed=(1 << 63) + 5), 64, 4294967303, 'c9d509e6ebf982e3')]
    if big: cases.append((scene(), 256, 1, 'f687d9fca4e29764'))
    for sc, grid, tick, want in cases:
        t0 = time.time()
        st = Stream(grid, 256.0, 256.0, 9.81, 240, hstep, 1 / 256, True)
        got = '%016x' % hash_state(SceneModel(st, sc).state(st, tick))
        assert got == want, (grid, tick, got, want)
        print('12.2', grid, tick, 'ok', round(time.time() - t0, 1), 's')
    t0 = time.time()
    storm = scene(spectrum=1, spreading=1, wind_speed_mps=20.0, wind_dir_deg=30.0)
    got = '%016x' % hash_state(cascaded_model_state(storm, [(1, 32, 4, 0), (8, 32, 0, 16)], 256.0, 256.0, 9.81, 240, hstep, 1 / 256, 5000))
    assert got == 'ecd7f544386b141a', got
    print('12.2 cascaded ok', round(time.time() - t0, 1), 's')


if __name__ == '__main__':
    for n in ['lite_modeled', 'lite_explicit', 'mobile_choppy', 'desktop_cascaded', 'mobile_wake']:
        t0 = time.time()
        run(n)
        print('  ', round(time.time() - t0, 1), 's')
    tables('--big' in sys.argv)
