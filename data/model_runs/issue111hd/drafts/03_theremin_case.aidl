# Request (electronics): "A case for my theremin kit board, 3 mm ply, finger-jointed.
# The board is 100 x 70 mm with M3 mounting holes 4 mm in from each corner, on 8 mm
# standoffs, 2 mm clear of every wall; 40 mm inside from floor to lid. On the front
# edge: the 6.35 mm audio jack (opening 10 wide x 10 tall, centred 20 mm from the
# board's left edge) and the DC jack (9 wide x 11 tall, centred 45 mm along).
# The pitch antenna leaves through a 6.5 mm hole in the middle of the right side,
# the volume loop through a 6.5 mm hole in the middle of the left side. The lid has
# two 7 mm holes for the pitch and volume pot shafts, 50 mm apart, 10 mm below the
# lid's middle, each labelled (PITCH, VOLUME, engraved 5 mm, 12 mm below the hole),
# and THEREMIN engraved in filled serif capitals 9 mm tall 20 mm above the middle.
# No vent."

import "std/enclosures.aidl"

thickness 3 mm

assembly theremin {
    box = board_enclosure(width=100 mm, height=70 mm, depth=40 mm, thickness=3 mm,
                          clearance=2 mm,
                          holes=[[4, 4], [96, 4], [4, 66], [96, 66]], hole_d=3.2 mm,
                          standoff=8 mm,
                          ports=[["front", 20, 10, 10], ["front", 45, 9, 11]],
                          vent="none", finger=10 mm)

    hole pots {
        pitch = Circle(center=(-25, 0), diameter=7)
        volume = Circle(center=(25, 0), diameter=7)
    }
    drawing lid_text {
        l1 = Text("PITCH", position=(-25, -12), size=5, valign="middle")
        l2 = Text("VOLUME", position=(25, -12), size=5, valign="middle")
        name = Text("THEREMIN", position=(0, 30), size=9, font="serif", valign="middle",
                    fill=true)
    }
    Rigid(pots, lid_text)
    At(pots.bb.center, box.lid.bb.center, dy=-10)
    CutInto(pots, box.lid)
    CutInto(lid_text, box.lid)

    hole pitch_antenna { c = Circle(center=(0, 0), diameter=6.5) }
    CenterInside(pitch_antenna, box.right)
    CutInto(pitch_antenna, box.right)

    hole volume_loop { c = Circle(center=(0, 0), diameter=6.5) }
    CenterInside(volume_loop, box.left)
    CutInto(volume_loop, box.left)

    assert box.length == 100 mm + 2 * 2 mm + 2 * 3 mm, "outer length: board + 2 mm clear + walls"
    assert box.wide == 70 mm + 2 * 2 mm + 2 * 3 mm, "outer width"
    assert box.tall == 40 mm + 2 * 3 mm, "40 mm inside"
    assert pots.volume.center.x - pots.pitch.center.x == 50 mm, "pots 50 apart"
    assert box.lid.bb.center_y - pots.pitch.center.y == 10 mm, "pots 10 below the lid's middle"
    assert pots.pitch.center.y - lid_text.l1.center.y == 12 mm, "labels 12 below"
    assert lid_text.name.center.y - box.lid.bb.center_y == 20 mm, "name 20 above the middle"
    assert pots.pitch.diameter == 7 mm and pitch_antenna.c.diameter == 6.5 mm, "hole sizes"
}
