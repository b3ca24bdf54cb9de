# Request (toys): a paper toy theatre for my kids' puppet shows, flat-pack in 3 mm ply, glued
# tabs. A proscenium front 300 mm wide, 230 mm to the shoulders and a domed top to 260 mm;
# a stage opening 200 mm wide from 46 mm up, straight sides 130 mm tall and an elliptical
# arch 30 mm high over them; "THEATRE" cut right through above the arch in 20 mm bold
# stencil letters, and a 5-point star engraved in each top corner. A stage floor 40 mm off
# the table, 183 mm deep from the front's face, tabbed into the front and both sides (three
# 30 mm tabs a side). Two side walls 190 deep x 200 tall, 10 mm in from the front's ends,
# tabbed into the front (two 30 mm tabs), each with a 130 x 10 mm slot 10 mm above the stage
# to slide the puppets in on sticks. Three 3.2 mm scenery slots 240 mm long across the floor,
# 50 mm apart, the first 70 mm back.

import "std/joints.aidl"

units mm
thickness 3 mm

t = 3 mm
W = 300 mm            # the front's width
side_x = 140 mm       # the side walls' mid-planes, either side of centre
side_h = 200 mm
side_d = 190 mm
stage = 40 mm         # the stage floor's top above the table
floor_d = 183 mm      # from the front's face to the floor's back edge
floor_w = 2 * side_x + t
open_w = 200 mm
open_bottom = 46 mm
open_h = 130 mm
arch_h = 30 mm

def front() -> solid {
    body = Rectangle(center=(0, 115), width=W, height=230)
    dome = Ellipse(center=(0, 230), rx=W / 2, ry=30)
    hole opening {
        r = Rectangle(center=(0, open_bottom + open_h / 2), width=open_w, height=open_h)
        arch = Ellipse(center=(0, open_bottom + open_h), rx=open_w / 2, ry=arch_h)
    }
    hole title {
        word = Text("THEATRE", (0, 222), size=20, font="sans:Bold", stencil=true)
    }
    drawing stars {
        left = Star(center=(-115, 230), points=5, outer_radius=12, inner_radius=5)
        right = Star(center=(115, 230), points=5, outer_radius=12, inner_radius=5)
    }
    left_m = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=2, tab=30 mm, screw=0,
                          rotation=90 deg, cx=-side_x, cy=side_h / 2)
    right_m = tab_and_slot(part="slot", length=side_h, thickness=t, tabs=2, tab=30 mm, screw=0,
                           rotation=90 deg, cx=side_x, cy=side_h / 2)
    floor_m = tab_and_slot(part="slot", length=floor_w, thickness=t, tabs=3, tab=30 mm, screw=0,
                           rotation=0, cx=0, cy=stage - t / 2)
}

def stage_floor() -> solid {
    body = Rectangle(bottom_left=(-floor_w / 2, 0), width=floor_w, height=floor_d)
    front_t = tab_and_slot(part="tab", length=floor_w, thickness=t, tabs=3, tab=30 mm, screw=0,
                           rotation=180 deg, cx=0, cy=0)
    left_t = tab_and_slot(part="tab", length=floor_d, thickness=t, tabs=3, tab=30 mm, screw=0,
                          rotation=90 deg, cx=-floor_w / 2, cy=floor_d / 2)
    right_t = tab_and_slot(part="tab", length=floor_d, thickness=t, tabs=3, tab=30 mm, screw=0,
                           rotation=-90 deg, cx=floor_w / 2, cy=floor_d / 2)
    hole scenery {
        s = Rectangle(center=(0, 70), width=240, height=3.2)
    }
    flats = LinearPattern(scenery, 3, (0, 50))
}

def side_wall() -> solid {
    body = Rectangle(bottom_left=(0, 0), width=side_d, height=side_h)
    front_t = tab_and_slot(part="tab", length=side_h, thickness=t, tabs=2, tab=30 mm, screw=0,
                           rotation=90 deg, cx=0, cy=side_h / 2)
    floor_m = tab_and_slot(part="slot", length=floor_d, thickness=t, tabs=3, tab=30 mm, screw=0,
                           rotation=0, cx=floor_d / 2, cy=stage - t / 2)
    hole puppets {
        s = Slot(center=(105, stage + 15), length=130, width=10)
    }
}

assembly theatre {
    proscenium = front()
    floor = stage_floor()
    left = side_wall()
    right = side_wall()

    # flat on the sheet
    Below(floor, proscenium, gap=10)
    AlignLeft(floor, proscenium)
    RightOf(left, proscenium, gap=10)
    AlignTop(left, proscenium)
    Below(right, left, gap=10)
    AlignLeft(right, left)

    # in 3D: x across, y from the front to the back, z up
    Place(proscenium, rotation=(90 deg, 0, 0), position=(0, t, 0))
    Place(floor, position=(0, 0, stage - t))
    Place(left, rotation=(90 deg, 0, 90 deg), position=(-side_x - t / 2, 0, 0))
    Place(right, rotation=(90 deg, 0, 90 deg), position=(side_x - t / 2, 0, 0))

    assert proscenium.body.bb.width == 300 mm, "front 300 wide"
    assert proscenium.dome.bb.top - proscenium.body.bb.bottom == 260 mm, "domed to 260"
    assert proscenium.opening.r.bb.width == 200 mm, "opening 200 wide"
    assert proscenium.opening.r.bb.bottom - proscenium.body.bb.bottom == 46 mm, "opening from 46 up"
    assert proscenium.opening.arch.bb.top - proscenium.opening.r.bb.top == 30 mm, "arch 30 high"
    assert proscenium.title.bb.bottom > proscenium.opening.bb.top + 5 mm, "title clear of the arch"
    assert W / 2 - side_x == 10 mm, "sides 10 mm in"
    assert len(floor.flats) == 3, "three scenery slots"
    assert floor.flats[0].s.center.y - floor.body.bb.bottom == 70 mm, "first 70 mm back"
    assert floor.flats[1].s.center.y - floor.flats[0].s.center.y == 50 mm, "50 apart"
    assert left.puppets.s.bb.bottom - stage == 10 mm, "puppet slot 10 above the stage"
}
