; The soup is already in the microwave: heating the pie heats the soup too.
(define (problem microwave-soup) (:domain microwave)
  (:objects pie soup - item microwave - appliance counter - surface)
  (:init (hand_empty) (on pie counter) (inside soup microwave) (closed microwave))
  (:goal (and (heated pie))))
