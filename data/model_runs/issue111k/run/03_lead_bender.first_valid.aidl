# Electronics resistor lead-bending gauge, 3 mm acrylic: a stepped strip 120 mm long. Five steps,
# each 20 mm long, of height 0.3, 0.4, 0.5, 0.6 and 0.7 inch (7.62, 10.16, 12.70, 15.24 and
# 17.78 mm: the breadboard spans a lead is bent around), all standing on one straight bottom
# edge, lowest at the left; then a 20 x 25 mm handle at the right end with a 5 mm hanging hole
# in its middle. Each step's span engraved on it ("0.3" ... "0.7"), 3 mm text, centred on the step.

thickness 3 mm

spans = [0.3, 0.4, 0.5, 0.6, 0.7]

solid gauge {
    for i in range(len(spans)) {
        step = Rectangle(bottom_left=(i * 20, 0), width=20, height=spans[i] * 25.4)
    }
    handle = Rectangle(bottom_left=(100, 0), width=20, height=25)

    hole hang {
        eye = Circle(center=(110, 12.5), diameter=5)
    }

    drawing labels {
        for i in range(len(spans)) {
            t = Text(f"{spans[i]:.1f}", (i * 20 + 10, spans[i] * 25.4 / 2), size=3,
                     valign="middle")
        }
    }

    assert self.bb.width == 120 mm, "strip 120 mm long"
    assert len(step) == 5, "five steps"
    assert step[0].width == 20 mm, "steps 20 mm long"
    assert step[0].height == 7.62 mm, "0.3 in step"
    assert step[1].height == 10.16 mm, "0.4 in step"
    assert step[2].height == 12.70 mm, "0.5 in step"
    assert step[3].height == 15.24 mm, "0.6 in step"
    assert step[4].height == 17.78 mm, "0.7 in step"
    assert step[4].bb.bottom == step[0].bb.bottom, "one straight bottom edge"
    assert handle.width == 20 mm and handle.height == 25 mm, "20 x 25 handle"
    assert handle.bb.right == self.bb.right, "handle at the right end"
    assert hang.eye.diameter == 5 mm, "5 mm hanging hole"
    assert hang.eye.center.x == handle.bb.center_x and hang.eye.center.y == handle.bb.center_y, "hole in the handle's middle"
    assert labels.t[2].size == 3 mm, "3 mm text"
    assert labels.t[2].position.x == step[2].bb.center_x, "label centred on its step"
}
