; A microwave heats whatever is inside it: a conditional effect (forall/when), so what turnon
; achieves -- and what is checked after it -- depends on the state it runs in.
; The predicates are the household's, which have paraphrases: every check is asked of the camera.
(define (domain microwave)
  (:requirements :typing :negative-preconditions :conditional-effects)
  (:types item appliance surface)
  (:predicates (holding ?o - item) (hand_empty) (on ?o - item ?s - surface) (inside ?o - item ?a - appliance)
               (open ?a - appliance) (closed ?a - appliance) (turned_on ?a - appliance) (heated ?o - item))
  (:action grasp
    :parameters (?o - item ?s - surface)
    :precondition (and (hand_empty) (on ?o ?s))
    :effect (and (holding ?o) (not (hand_empty)) (not (on ?o ?s))))
  (:action placein
    :parameters (?o - item ?a - appliance)
    :precondition (and (holding ?o) (open ?a))
    :effect (and (inside ?o ?a) (hand_empty) (not (holding ?o))))
  (:action open
    :parameters (?a - appliance)
    :precondition (and (closed ?a) (hand_empty) (not (turned_on ?a)))
    :effect (and (open ?a) (not (closed ?a))))
  (:action close
    :parameters (?a - appliance)
    :precondition (and (open ?a) (hand_empty))
    :effect (and (closed ?a) (not (open ?a))))
  (:action turnon
    :parameters (?a - appliance)
    :precondition (and (closed ?a) (not (turned_on ?a)))
    :effect (and (turned_on ?a)
                 (forall (?o - item) (when (inside ?o ?a) (heated ?o))))))
