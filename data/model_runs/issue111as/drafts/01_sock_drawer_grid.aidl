# Request (home): an egg-crate divider grid for a sock drawer whose inside is 380 mm wide
# (left to right) and 300 mm deep, cut from 3 mm MDF. Two long strips 378 mm long and three
# short strips 298 mm long (2 mm shorter than the drawer each way), all 80 mm tall. The strips
# cross in halving joints: each long strip has three 3 mm slots 40 mm deep from its TOP edge,
# at 1/4, 1/2 and 3/4 of its length; each short strip has two 3 mm slots 40 mm deep from its
# BOTTOM edge, at 1/3 and 2/3 of its length, so the grid makes 4 x 3 = 12 cells and all tops
# are flush. Each long strip has two finger slots 30 x 14 mm, 12 mm below its top (centre),
# centred in its two end cells, to lift the grid out. "SOCKS" engraved 12 mm tall in the middle
# of the first long strip's lower half.

import "std/joints.aidl"

thickness 3 mm

param long_len = 378 mm, min = 200 mm, max = 600 mm
param short_len = 298 mm, min = 150 mm, max = 500 mm
param tall = 80 mm, min = 40 mm, max = 150 mm
mat = 3 mm

def long_strip(label="") -> solid {
    body = Rectangle(center=(0, 0), width=long_len, height=tall)
    for i in range(3) {
        slot = cross_halving(depth=tall / 2, thickness=mat, cx=-long_len / 2 + (i + 1) * long_len / 4, cy=tall / 2)
    }
    hole lift {
        left = Slot(center=(-long_len * 3 / 8, tall / 2 - 12 mm), length=30, width=14)
        right = Slot(center=(long_len * 3 / 8, tall / 2 - 12 mm), length=30, width=14)
    }
    if label != "" {
        drawing mark {
            word = Text(label, position=(0, -tall / 4), size=12, valign="middle")
        }
    }
}

def short_strip() -> solid {
    body = Rectangle(center=(0, 0), width=short_len, height=tall)
    for i in range(2) {
        slot = cross_halving(depth=tall / 2, thickness=mat, cx=-short_len / 2 + (i + 1) * short_len / 3, cy=-tall / 2, rotation=180 deg)
    }
}

assembly sock_grid {
    long_a = long_strip(label="SOCKS")
    long_b = long_strip()
    short_a = short_strip()
    short_b = short_strip()
    short_c = short_strip()

    Below(long_b, long_a, gap=5)
    AlignLeft(long_b, long_a)
    Below(short_a, long_b, gap=5)
    AlignLeft(short_a, long_a)
    Below(short_b, short_a, gap=5)
    AlignLeft(short_b, long_a)
    Below(short_c, short_b, gap=5)
    AlignLeft(short_c, long_a)

    # the request's numbers
    assert long_a.body.bb.width == 378 mm, "long strips 378 mm"
    assert short_a.body.bb.width == 298 mm, "short strips 298 mm"
    assert long_a.body.bb.height == 80 mm and short_a.body.bb.height == 80 mm, "80 mm tall"
    assert 380 mm - long_a.body.bb.width == 2 mm, "2 mm play left to right"
    assert 300 mm - short_a.body.bb.width == 2 mm, "2 mm play front to back"
    assert len(long_a.slot) == 3 and len(short_a.slot) == 2, "3 slots per long strip, 2 per short"
    assert long_a.slot[0].depth + short_a.slot[0].depth == 80 mm, "the halvings meet: depths add to the height"
    assert long_a.slot[1].cut.bb.center_x == long_a.body.bb.center_x, "middle slot at half the length"
    assert long_a.slot[0].cut.bb.top == long_a.body.bb.top, "long strip slots from the top"
    assert short_a.slot[0].cut.bb.bottom == short_a.body.bb.bottom, "short strip slots from the bottom"
    assert abs(long_a.slot[0].cut.bb.width - 3 mm) < 0.01 mm, "slots 3 mm wide"
    assert long_a.body.bb.top - long_a.lift.left.center.y == 12 mm, "finger slot 12 mm below the top"
    assert long_a.lift.left.length == 30 mm and long_a.lift.left.width == 14 mm, "finger slot 30 x 14"
}
