# Request (kitchen): a wall-hung kitchen conversion chart, 3 mm birch ply, 200 x 280 mm with
# 10 mm rounded corners and two 5 mm hanging holes 15 mm in from the top corners.
# "KITCHEN" and "CONVERSIONS" engraved filled at the top, a line under them. Left column:
# OVEN, gas marks 1 to 9 with their Celsius and Fahrenheit (140/275 up to 240/475 in the
# usual steps). Right column: VOLUME, 1 CUP 240 ML, 3/4 CUP 180, 1/2 CUP 120, 1/3 CUP 80,
# 1/4 CUP 60, 1 TBSP 15, 1 TSP 5. A vertical line between the columns. Below a line:
# WEIGHT, 1 OZ = 28 G, 4 OZ = 113 G, 8 OZ = 227 G, 1 LB = 454 G. Tables in single strokes.

import "std/plates.aidl"

units mm
thickness 3 mm

gas_c = [140, 150, 170, 180, 190, 200, 220, 230, 240]
gas_f = [275, 300, 325, 350, 375, 400, 425, 450, 475]
vol_name = ["1 CUP", "3/4 CUP", "1/2 CUP", "1/3 CUP", "1/4 CUP", "1 TBSP", "1 TSP"]
vol_ml = [240, 180, 120, 80, 60, 15, 5]
weights = ["1 OZ = 28 G", "4 OZ = 113 G", "8 OZ = 227 G", "1 LB = 454 G"]
row = 11 mm       # row pitch of both tables
top_row = 60 mm   # y of the first row

solid chart {
    body = RoundedRectangle(center=(0, 0), width=200, height=280, corner_radius=10)
    hole hang {
        for x in [-85, 85] {
            h = Circle(center=(x, 125), diameter=5)
        }
    }

    drawing title {
        t1 = Text("KITCHEN", position=(0, 108), size=16, font="sans:Bold", fill=true)
        t2 = Text("CONVERSIONS", position=(0, 92), size=8, font="sans:Bold", fill=true)
        rule = Line((-85, 84), (85, 84))
    }

    drawing oven {
        head = Text("OVEN", position=(-50, 72), size=6)
        for i in range(9) {
            g = Text(f"GAS {i + 1}", position=(-90, top_row - i * row), size=4.5, anchor="start")
            # FIX after the first valid program: W0513, "140 C" ran into "275 F" (each ~21 mm
            # wide at size 4.5); three columns ~11 mm apart, both numbers right-aligned
            c = Text(f"{gas_c[i]:.0f} C", position=(-38, top_row - i * row), size=4.5, anchor="end")
            f = Text(f"{gas_f[i]:.0f} F", position=(-6, top_row - i * row), size=4.5, anchor="end")
        }
    }

    drawing volume {
        head = Text("VOLUME", position=(50, 72), size=6)
        for i in range(7) {
            n = Text(vol_name[i], position=(12, top_row - i * row), size=4.5, anchor="start")
            v = Text(f"{vol_ml[i]:.0f} ML", position=(88, top_row - i * row), size=4.5, anchor="end")
        }
    }

    drawing rules {
        divider = Line((0, 80), (0, -34))
        under = Line((-85, -40), (85, -40))
    }

    drawing weight {
        head = Text("WEIGHT", position=(0, -54), size=6)
        for i in range(4) {
            w = Text(weights[i], position=(0, -68 - i * row), size=4.5)
        }
    }

    # the request's numbers
    assert body.bb.width == 200 mm and body.bb.height == 280 mm, "200 x 280"
    assert len(gas_c) == 9 and len(gas_f) == 9, "gas marks 1 to 9"
    assert gas_c[3] == 180 and gas_f[3] == 350, "gas 4 is 180 C / 350 F"
    assert len(vol_name) == 7 and len(vol_ml) == 7, "seven volume rows"
    assert body.bb.top - hang.h[0].center.y == 15 mm, "hanging holes 15 mm from the top"
    assert hang.h[0].center.x - body.bb.left == 15 mm, "hanging holes 15 mm from the side"
}
