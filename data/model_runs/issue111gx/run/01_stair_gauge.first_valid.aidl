# Request: a stair-tread template jig ("stair gauge") to copy the exact length and end
# angles of a tread between two out-of-square stringer walls. Cut from 6 mm plywood, four parts:
# - two identical bars, 450 mm long x 40 mm wide (4 mm corner radius), which overlap and are
#   clamped together by two M6 bolts running in a centreline slot 300 mm long (end to end)
#   x 6.5 mm wide that starts 40 mm from the bar's inner end; at the outer end a 6.5 mm pivot
#   hole 20 mm from the end and a 6.5 mm locking hole 40 mm further in; an engraved scale along
#   the slot: a tick every 10 mm (every 50 mm longer and numbered 0 to 300);
# - two end paddles, 150 mm x 70 mm, that press against the walls: a 6.5 mm pivot hole on the
#   centre line 15 mm above the wall edge, and an arc slot 6.5 mm wide at 40 mm radius round
#   the pivot, from 45 to 135 degrees, for the locking bolt; "WALL EDGE" engraved along the
#   wall edge.

units mm
thickness 6 mm

param bar_len = 450 mm, min = 300 mm, max = 600 mm
param bar_w = 40 mm, min = 30 mm, max = 60 mm
param slot_len = 300 mm, min = 150 mm, max = 400 mm
param bolt_d = 6.5 mm, min = 4.5 mm, max = 8.5 mm

def bar() -> solid {
    body = RoundedRectangle(center=(0, 0), width=bar_len, height=bar_w, corner_radius=4)
    hole slot {
        s = Slot(center=(-bar_len / 2 + 40 + slot_len / 2, 0), length=slot_len, width=bolt_d)
    }
    hole pivot {
        c = Circle(center=(bar_len / 2 - 20, 0), diameter=bolt_d)
    }
    hole lock {
        c = Circle(center=(bar_len / 2 - 60, 0), diameter=bolt_d)
    }
    drawing scale {
        for i in range(floor(slot_len / 10 mm) + 1) {
            tick = Line((-bar_len / 2 + 40 + i * 10, 6), (-bar_len / 2 + 40 + i * 10, 13 if i % 5 == 0 else 10))
        }
        for j in range(floor(slot_len / 50 mm) + 1) {
            num = Text(str(j * 50), position=(-bar_len / 2 + 40 + j * 50, 14.5), size=3)
        }
    }
    assert body.bb.width == 450 mm, "bar 450 mm long"
    assert body.bb.height == 40 mm, "bar 40 mm wide"
    assert slot.s.length == 300 mm, "slot 300 mm end to end"
    assert slot.s.width == 6.5 mm, "slot 6.5 mm wide"
    assert slot.s.bb.left - body.bb.left == 40 mm, "slot starts 40 mm from the inner end"
    assert body.bb.right - pivot.c.center.x == 20 mm, "pivot 20 mm from the outer end"
    assert pivot.c.center.x - lock.c.center.x == 40 mm, "lock hole 40 mm further in"
    assert len(scale.tick) == 31, "a tick every 10 mm over 300 mm"
}

def paddle() -> solid {
    body = Rectangle(center=(0, 0), width=150, height=70)
    hole pivot {
        c = Circle(center=(0, -35 + 15), diameter=bolt_d)
    }
    hole lock {
        a = ArcSlot(center=(0, -35 + 15), radius=40, start_angle=45 deg, end_angle=135 deg, width=bolt_d)
    }
    drawing label {
        t = Text("WALL EDGE", position=(0, -31), size=4)
    }
    assert body.bb.width == 150 mm and body.bb.height == 70 mm, "paddle 150 x 70"
    assert pivot.c.center.y - body.bb.bottom == 15 mm, "pivot 15 mm above the wall edge"
    assert distance(label, pivot) >= 2 mm, "label clear of the pivot hole"
}

assembly stair_gauge {
    bar_a = bar()
    bar_b = bar()
    paddle_a = paddle()
    paddle_b = paddle()
    Below(bar_b, bar_a, gap=10)
    AlignLeft(bar_b, bar_a)
    Below(paddle_a, bar_b, gap=10)
    AlignLeft(paddle_a, bar_b)
    RightOf(paddle_b, paddle_a, gap=10)
    AlignTop(paddle_b, paddle_a)
}
