import sys, subprocess, zlib, struct
src, x, y, w, h, dst = sys.argv[1], *map(int, sys.argv[2:6]), sys.argv[6]
data = subprocess.run(['convert', src, 'ppm:-'], capture_output=True).stdout
# parse P6 header
parts = []; i = 0
while len(parts) < 4:
    while data[i:i+1].isspace(): i += 1
    if data[i:i+1] == b'#':
        while data[i:i+1] != b'\n': i += 1
        continue
    j = i
    while not data[j:j+1].isspace(): j += 1
    parts.append(data[i:j]); i = j
i += 1
W, H = int(parts[1]), int(parts[2])
px = data[i:]
rows = []
for r in range(y, min(y+h, H)):
    row = px[(r*W + x)*3:(r*W + min(x+w, W))*3]
    rows.append(b'\x00' + row)
ww = min(x+w, W) - x
raw = b''.join(rows)
def chunk(t, d): return struct.pack('>I', len(d)) + t + d + struct.pack('>I', zlib.crc32(t+d) & 0xffffffff)
png = b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', ww, len(rows), 8, 2, 0, 0, 0)) + chunk(b'IDAT', zlib.compress(raw)) + chunk(b'IEND', b'')
open(dst, 'wb').write(png)
print(W, H)
