; Only the pie is heated: the microwave is empty before it goes in.
(define (problem microwave-pie) (:domain microwave)
  (:objects pie soup - item microwave - appliance counter - surface)
  (:init (hand_empty) (on pie counter) (on soup counter) (closed microwave))
  (:goal (and (heated pie))))
