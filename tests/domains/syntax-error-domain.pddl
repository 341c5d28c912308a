(define (domain broken)
  (:requirements :strips)
  (:predicates (p ?x))
  (:action a :parameters (?x)
    :precondition (p ?x)
    :effect (and (not (p ?x)))
  ; the closing parentheses of the action and the domain are missing
