"""Writes potrace-shapes.pbm (64x48, plain PBM): a ring with a dot inside its hole
(three nesting levels), a square turned 30 degrees with a square hole, and a bar.
Run: python3 potrace-shapes-pbm.py > potrace-shapes.pbm
"""
import math

W, H = 64, 48


def ink(x, y):
    px, py = x + 0.5, y + 0.5
    r = math.hypot(px - 19, py - 22)
    if 11 <= r <= 17 or r <= 5:
        return 1
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    u = (px - 50) * c + (py - 16) * s
    v = -(px - 50) * s + (py - 16) * c
    if 3.5 <= max(abs(u), abs(v)) <= 8:
        return 1
    if 38 <= px <= 61 and 37 <= py <= 43:
        return 1
    return 0


print("P1")
print("# potrace-shapes.pbm, made by potrace-shapes-pbm.py")
print(W, H)
for y in range(H):
    print("".join(str(ink(x, y)) for x in range(W)))
