; Numeric fluents beyond action costs: refused with the requirement named.
(define (domain tank)
  (:requirements :typing :numeric-fluents)
  (:types tank)
  (:functions (level ?t - tank) - number)
  (:action fill :parameters (?t - tank)
    :precondition (< (level ?t) 10)
    :effect (increase (level ?t) 1)))
