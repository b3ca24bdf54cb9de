# A laser-cut box of six panels, shown unfolded (as a net) in the assembly view.
# Each panel is a separate part: `aidl parts` lists them (the long sides, the
# short sides and the lid/bottom pairs come out as copies), and
#   aidl render examples/laser_box.aidl --layout sheet --sheet 300x200mm -o box.dxf
# nests them flat on one sheet for the laser; `--kerf 0.15mm` makes every panel
# come out at its designed size. The panels butt-join and are glued.
# Try: --set length=120mm  --set depth=70mm  --set height=50mm

units mm
param length = 100 mm, min = 60 mm, max = 200 mm, step = 5 mm
param depth = 60 mm, min = 45 mm, max = 120 mm, step = 5 mm
param height = 40 mm, min = 25 mm, max = 100 mm, step = 5 mm
param wall = 3 mm
thickness 3 mm

gap = 4 mm
side_len = depth - 2 * wall  # the short sides fit between the long ones

assembly box {
    solid bottom {
        body = Rectangle(center=(0, 0), width=length, height=depth)
    }
    solid lid {
        body = Rectangle(center=(0, depth + height + 2 * gap), width=length, height=depth)
        hole grip {
            s = Slot(start=(-15, depth + height + 2 * gap), end=(15, depth + height + 2 * gap), width=10)
        }
        drawing label {
            t = Text("PARTS", center=(0, depth + height + 2 * gap - 18), size=7)
        }
    }
    solid front {
        body = RoundedRectangle(center=(0, -(depth + height) / 2 - gap), width=length, height=height, corner_radius=2)
        hole vent {
            for i in range(3) {
                v = Slot(start=(-20, -(depth + height) / 2 - gap + (i - 1) * 8), end=(20, -(depth + height) / 2 - gap + (i - 1) * 8), width=4)
            }
        }
    }
    solid back {
        body = RoundedRectangle(center=(0, (depth + height) / 2 + gap), width=length, height=height, corner_radius=2)
        hole vent {
            for i in range(3) {
                v = Slot(start=(-20, (depth + height) / 2 + gap + (i - 1) * 8), end=(20, (depth + height) / 2 + gap + (i - 1) * 8), width=4)
            }
        }
    }
    solid left {
        body = RoundedRectangle(center=(-(length + height) / 2 - gap, 0), width=height, height=side_len, corner_radius=2)
        hole handle {
            h = Slot(start=(-(length + height) / 2 - gap, -12), end=(-(length + height) / 2 - gap, 12), width=8)
        }
    }
    solid right {
        body = RoundedRectangle(center=((length + height) / 2 + gap, 0), width=height, height=side_len, corner_radius=2)
        hole handle {
            h = Slot(start=((length + height) / 2 + gap, -12), end=((length + height) / 2 + gap, 12), width=8)
        }
    }
}
